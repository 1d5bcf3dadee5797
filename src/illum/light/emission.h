// What an emitter emits (its radiance, intensity or irradiance, by the light), in both modes: the RGB for
// RGB mode, and for spectral mode either the spectrum the scene gave (named, sampled, blackbody;
// normalised to luminance 1 as pbrt-v4 does) or, for an RGB value, that RGB uplifted as an illuminant
// (uplift.h). Both carry the same scale.
#pragma once

#include <memory>

#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/quantity.h"
#include "illum/radiometry/uplift.h"

namespace illum {

struct Emission {
    Color3 rgb{1.0f};
    std::shared_ptr<const DenselySampledSpectrum> spectrum; // null: rgb uplifted
    float spectrum_scale = 1;

    Emission() = default;
    explicit Emission(Color3 c) : rgb(c) {}
    Emission(Color3 c, std::shared_ptr<const DenselySampledSpectrum> s) : rgb(c), spectrum(std::move(s)) {}
    // An RGB quantity (radiance, intensity, ...) as an emission: its RGB, uplifted in spectral mode.
    template <int W, int M, int S, class T>
    Emission(Quantity3<W, M, S, T> q) : rgb(q.rgb()) {}

    SampledSpectrum at(const SampledWavelengths& w) const {
        if (!w.spectral()) return SampledSpectrum(rgb);
        if (spectrum) return spectrum->sample(w) * spectrum_scale;
        return uplift_illuminant(rgb, w);
    }
    // RGB mode's value (light selection by power, which does not depend on the mode).
    SampledSpectrum rgb_value() const { return SampledSpectrum(rgb); }
    Emission& operator*=(float s) {
        rgb *= s;
        spectrum_scale *= s;
        return *this;
    }
    Emission operator*(float s) const { return Emission(*this) *= s; }
};

} // namespace illum
