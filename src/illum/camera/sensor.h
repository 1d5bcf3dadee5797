// The film's sensor (pbrt-v4's PixelSensor for its default "cie1931" sensor): in spectral mode it turns
// the radiance at a camera sample's wavelengths into the output colour space's RGB through the CIE 1931
// matching functions, XYZ = E[x̄(λ) L(λ) / p(λ)] over the sample's wavelengths (= ∫ x̄ L dλ), so a
// luminance-1 illuminant gives Y = 1; in RGB mode the radiance already is RGB. Either way the result is
// scaled by the imaging ratio exposure time · ISO / 100 (1 by default) and, with a white balance
// temperature, adapted from the CIE daylight of that temperature to the output space's white (von Kries in
// the Bradford cone space, as pbrt-v4's WhiteBalance).
#pragma once

#include <optional>

#include "illum/radiometry/color_space.h"
#include "illum/radiometry/densely_sampled_spectrum.h"
#include "illum/radiometry/quantity.h"

namespace illum {

class Sensor {
public:
    // white_balance_kelvin: 0 for none (pbrt-v4's default for "cie1931").
    explicit Sensor(const RGBColorSpace& output = RGBColorSpace::srgb(), float imaging_ratio = 1,
                    float white_balance_kelvin = 0);

    // The film value of one camera sample's radiance.
    Color3 to_rgb(const Radiance3& l, const SampledWavelengths& w) const {
        if (!w.spectral()) return identity_ ? l.rgb() : apply(rgb_matrix_, l.rgb());
        SampledSpectrum v = safe_div(l.s, w.pdf_spectrum());
        double xyz[3] = {0, 0, 0};
        for (int i = 0; i < kSpectrumSamples; ++i) {
            xyz[0] += x_(w.lambda[i]) * v[i];
            xyz[1] += y_(w.lambda[i]) * v[i];
            xyz[2] += z_(w.lambda[i]) * v[i];
        }
        Color3 c(float(xyz[0] / kSpectrumSamples), float(xyz[1] / kSpectrumSamples),
                 float(xyz[2] / kSpectrumSamples));
        return apply(xyz_matrix_, c);
    }
    const RGBColorSpace& output() const { return *output_; }
    float imaging_ratio() const { return imaging_ratio_; }

private:
    static Color3 apply(const float m[9], Color3 c) {
        return {m[0] * c.r + m[1] * c.g + m[2] * c.b, m[3] * c.r + m[4] * c.g + m[5] * c.b,
                m[6] * c.r + m[7] * c.g + m[8] * c.b};
    }
    const RGBColorSpace* output_;
    float imaging_ratio_;
    bool identity_ = true;
    float xyz_matrix_[9]; // output RGB from XYZ, white balance and imaging ratio included
    float rgb_matrix_[9]; // the same for RGB mode's output-space RGB
    DenselySampledSpectrum x_, y_, z_;
};

} // namespace illum
