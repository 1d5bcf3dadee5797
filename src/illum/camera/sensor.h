// The film's sensor (pbrt-v4's PixelSensor for its default "cie1931" sensor): in spectral mode it turns
// the radiance at a camera sample's wavelengths into the output colour space's RGB through the CIE 1931
// matching functions, XYZ = E[x̄(λ) L(λ) / p(λ)] over the sample's wavelengths (= ∫ x̄ L dλ), so a
// luminance-1 illuminant gives Y = 1; in RGB mode the radiance already is RGB. Either way the result is
// scaled by the imaging ratio exposure time · ISO / 100 (1 by default) and, with a white balance
// temperature, adapted from the CIE daylight of that temperature to the output space's white (von Kries in
// the Bradford cone space, as pbrt-v4's WhiteBalance).
#pragma once

#include <algorithm>
#include <limits>
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
    // to_rgb of each unit spectrum e_i at these wavelengths (the columns of its matrix, FilmResponse): in
    // spectral mode M c̄(λ_i) / (N p(λ_i)), with M the output matrix and c̄ the matching functions (0 where
    // p(λ_i) = 0); in RGB mode the output matrix's columns (the fourth sample is unused: 0).
    void unit_responses(const SampledWavelengths& w, Color3 out[kSpectrumSamples]) const {
        if (!w.spectral()) {
            for (int i = 0; i < kSpectrumSamples; ++i) {
                Color3 e(i == 0 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.0f, i == 2 ? 1.0f : 0.0f);
                out[i] = identity_ ? e : apply(rgb_matrix_, e);
            }
            return;
        }
        for (int i = 0; i < kSpectrumSamples; ++i) {
            const float k = w.pdf[i] != 0 ? 1 / (w.pdf[i] * float(kSpectrumSamples)) : 0.0f;
            out[i] =
                apply(xyz_matrix_, Color3(x_(w.lambda[i]) * k, y_(w.lambda[i]) * k, z_(w.lambda[i]) * k));
        }
    }
    // A sample's value as the film adds it (pbrt-v4's RGBFilm::AddSample and AddSplat): to_rgb, scaled
    // down, when the largest component of its sensor value (imaging ratio times XYZ, before white
    // balance: pbrt-v4's sensor RGB for "cie1931") exceeds the film's maxcomponentvalue, so that
    // component equals it; the hue is kept. Without a limit (the default, +inf) this is to_rgb.
    Color3 to_film(const Radiance3& l, const SampledWavelengths& w) const {
        Color3 c = to_rgb(l, w);
        if (!limited()) return c;
        return c * limit_scale(sensor_xyz(l, w));
    }
    void set_max_component_value(float v) { max_component_ = v; }
    float max_component_value() const { return max_component_; }
    // Whether the film limits its samples (a finite maxcomponentvalue).
    bool limited() const { return max_component_ < std::numeric_limits<float>::infinity(); }
    // Imaging ratio times the sample's XYZ: its sensor value, which maxcomponentvalue limits.
    Color3 sensor_xyz(const Radiance3& l, const SampledWavelengths& w) const {
        if (!w.spectral()) return apply(xyz_from_rgb_, l.rgb());
        SampledSpectrum v = safe_div(l.s, w.pdf_spectrum());
        double xyz[3] = {0, 0, 0};
        for (int i = 0; i < kSpectrumSamples; ++i) {
            xyz[0] += x_(w.lambda[i]) * v[i];
            xyz[1] += y_(w.lambda[i]) * v[i];
            xyz[2] += z_(w.lambda[i]) * v[i];
        }
        double k = double(imaging_ratio_) / kSpectrumSamples;
        return {float(xyz[0] * k), float(xyz[1] * k), float(xyz[2] * k)};
    }
    // The factor to_film applies to a sample of this sensor value (1 below the limit). A sample whose parts
    // were found at different wavelength densities (VCM's estimate: its joined and merged parts may have
    // the secondary wavelengths terminated) has the sum of its parts' sensor values.
    float limit_scale(Color3 sensor_value) const {
        float m = std::max(sensor_value.r, std::max(sensor_value.g, sensor_value.b));
        return m > max_component_ ? max_component_ / m : 1.0f;
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
    float xyz_matrix_[9];   // output RGB from XYZ, white balance and imaging ratio included
    float rgb_matrix_[9];   // the same for RGB mode's output-space RGB
    float xyz_from_rgb_[9]; // imaging ratio times XYZ from the output space's RGB (RGB mode's sensor value)
    float max_component_ = std::numeric_limits<float>::infinity();
    DenselySampledSpectrum x_, y_, z_;
};

// The film's response at one set of wavelengths, for the many values of one sample (a bidirectional sample's
// estimate and its splats, an SPPM iteration's gathers): Sensor::to_rgb is linear in the spectrum, so it is
// the 3 × 4 matrix of its responses to the four unit spectra (Sensor::unit_responses), one matrix-vector
// product per value instead of the colour-matching lookups. Equal to to_rgb within float rounding. film() is
// to_film: the sensor's own where a maxcomponentvalue makes it non-linear.
class FilmResponse {
public:
    FilmResponse(const Sensor& sensor, const SampledWavelengths& lambda) : sensor_(&sensor), lambda_(lambda) {
        sensor.unit_responses(lambda, column_);
        linear_ = !sensor.limited();
    }
    Color3 rgb(const SampledSpectrum& s) const {
        Color3 c = column_[0] * s[0];
        for (int i = 1; i < kSpectrumSamples; ++i) c += column_[i] * s[i];
        return c;
    }
    Color3 film(const Radiance3& l) const { return linear_ ? rgb(l.s) : sensor_->to_film(l, lambda_); }

private:
    const Sensor* sensor_;
    SampledWavelengths lambda_;
    Color3 column_[kSpectrumSamples];
    bool linear_ = true;
};

} // namespace illum
