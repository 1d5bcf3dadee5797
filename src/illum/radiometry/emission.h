// What an emitter emits (its radiance, intensity or irradiance, by the light), in both modes: the RGB for
// RGB mode, and for spectral mode either the spectrum the scene gave (named, sampled, blackbody;
// normalised to luminance 1 as pbrt-v4 does) or, for an RGB value, that RGB uplifted as an illuminant
// (uplift.h). Both carry the same scale.
#pragma once

#include <array>
#include <memory>

#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/quantity.h"
#include "illum/radiometry/uplift.h"

namespace illum {

struct Emission {
    Color3 rgb{1.0f};
    // The spectrum in spectral mode, without spectrum_scale: the given one, or for an RGB value its
    // uplifted illuminant spectrum in each colour space (tabulated once, so a lookup is four table reads).
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
    std::shared_ptr<const std::array<DenselySampledSpectrum, RGBColorSpace::kCount>> uplifted;
    float spectrum_scale = 1;

    Emission() : Emission(Color3(1.0f)) {}
    explicit Emission(Color3 c) : rgb(c), uplifted(uplift_tables(c)) {}
    Emission(Color3 c, std::shared_ptr<const DenselySampledSpectrum> s) : rgb(c), spectrum(std::move(s)) {}
    // An RGB quantity (radiance, intensity, ...) as an emission: its RGB, uplifted in spectral mode.
    template <int W, int M, int S, class T>
    Emission(Quantity3<W, M, S, T> q) : Emission(q.rgb()) {}

    SampledSpectrum at(const SampledWavelengths& w) const {
        if (!w.spectral()) return SampledSpectrum(rgb);
        const DenselySampledSpectrum& d =
            spectrum ? *spectrum : (*uplifted)[std::size_t(w.color_space->index())];
        return d.sample(w) * spectrum_scale;
    }
    // RGB mode's value (light selection by power, which does not depend on the mode).
    SampledSpectrum rgb_value() const { return SampledSpectrum(rgb); }
    Emission& operator*=(float s) {
        rgb *= s;
        spectrum_scale *= s;
        return *this;
    }
    Emission operator*(float s) const { return Emission(*this) *= s; }

private:
    static std::shared_ptr<const std::array<DenselySampledSpectrum, RGBColorSpace::kCount>>
    uplift_tables(Color3 c) {
        auto t = std::make_shared<std::array<DenselySampledSpectrum, RGBColorSpace::kCount>>();
        for (int i = 0; i < RGBColorSpace::kCount; ++i) {
            const RGBColorSpace& cs = RGBColorSpace::by_index(i);
            UpliftedRgb u = uplift_unbounded_poly(c, cs);
            (*t)[std::size_t(i)] =
                DenselySampledSpectrum::from([&](double l) { return u(l) * cs.illuminant(l); });
        }
        return t;
    }
};

} // namespace illum
