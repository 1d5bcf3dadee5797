// The wavelengths a camera path carries and how they were chosen. In spectral mode four wavelengths are
// drawn per camera sample: a hero wavelength importance-sampled over the visible range and three more at
// equal offsets of the sample (Wilkie et al. 2014, "Hero Wavelength Spectral Sampling", EGSR), so the
// four share one path and each has the same density. In RGB mode there are no wavelengths: a
// SampledSpectrum holds RGB and every conversion below is the identity on it.
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/radiometry/sampled_spectrum.h"

namespace illum {

class RGBColorSpace;

inline constexpr float kVisibleMin = 360, kVisibleMax = 830; // nm
inline constexpr float kLambdaDLine = 587.56f; // the helium d line, where a glass's n_d is given

// The visible-wavelength density of PBR 4th ed. §5.4.2 (pbrt-v4's SampleVisibleWavelengths): a fit to
// the CIE Y curve's shape, p(λ) ∝ 1 / cosh²(0.0072 (λ − 538)) on [360, 830] nm.
inline float visible_wavelength_pdf(float lambda) {
    if (lambda < kVisibleMin || lambda > kVisibleMax) return 0;
    float c = std::cosh(0.0072f * (lambda - 538));
    return 0.0039398042f / (c * c);
}
// Its inverse CDF (in double, for the table below).
inline double sample_visible_wavelength(double u) {
    return 538 - 138.888889 * std::atanh(0.85691062 - 1.82750197 * u);
}

// What the renderer samples: that inverse CDF at kVisibleBins + 1 nodes u = i / kVisibleBins, linear in
// between, so its density is the exact piecewise constant (1 / kVisibleBins) / (λ_{i+1} - λ_i) on each
// bin (within 0.2% of the analytic one) and a sample costs a multiply and a table read instead of an
// atanh and a cosh (8% of a spectral Cornell box's time).
inline constexpr int kVisibleBins = 256;
struct VisibleWavelengthTable {
    float lambda[kVisibleBins + 1];
    float pdf[kVisibleBins];
    VisibleWavelengthTable();
};
const VisibleWavelengthTable& visible_wavelength_table();
// One wavelength from u in [0, 1) and its density.
inline float sample_visible_tabulated(float u, float* pdf) {
    const VisibleWavelengthTable& t = visible_wavelength_table();
    float x = u * kVisibleBins;
    int i = x < float(kVisibleBins - 1) ? int(x) : kVisibleBins - 1;
    *pdf = t.pdf[i];
    return t.lambda[i] + (x - float(i)) * (t.lambda[i + 1] - t.lambda[i]);
}

struct SampledWavelengths {
    float lambda[kSpectrumSamples] = {kLambdaDLine, kLambdaDLine, kLambdaDLine, kLambdaDLine};
    float pdf[kSpectrumSamples] = {1, 1, 1, 1};
    // The colour space RGB inputs are uplifted from (spectral mode); null in RGB mode.
    const RGBColorSpace* color_space = nullptr;

    bool spectral() const { return color_space != nullptr; }
    float hero() const { return lambda[0]; }

    static SampledWavelengths rgb_mode() { return {}; }
    // Four wavelengths for one sample u in [0, 1): the hero at u, the others at u + i/4 (mod 1).
    static SampledWavelengths sample_visible(float u, const RGBColorSpace* cs) {
        SampledWavelengths w;
        w.color_space = cs;
        for (int i = 0; i < kSpectrumSamples; ++i) {
            float ui = u + float(i) / kSpectrumSamples;
            if (ui >= 1) ui -= 1;
            w.lambda[i] = sample_visible_tabulated(ui, &w.pdf[i]);
        }
        return w;
    }
    // A wavelength-dependent event (refraction by a dispersive index, a dispersive lens) sends each
    // wavelength its own way: the path keeps the hero only. Its estimate then stands for all four
    // strategies, so its density is divided by their number (the one-sample MIS of Wilkie et al. with
    // the others' contributions zero), and the others get density 0, which the film skips.
    // In RGB mode there is nothing to terminate.
    void terminate_secondary() {
        if (!spectral() || secondary_terminated()) return;
        for (int i = 1; i < kSpectrumSamples; ++i) pdf[i] = 0;
        pdf[0] /= kSpectrumSamples;
    }
    bool secondary_terminated() const {
        for (int i = 1; i < kSpectrumSamples; ++i)
            if (pdf[i] != 0) return false;
        return true;
    }
    SampledSpectrum pdf_spectrum() const { return {pdf[0], pdf[1], pdf[2], pdf[3]}; }
};

} // namespace illum
