// RGB colour spaces: primaries and a white illuminant, the RGB <-> XYZ matrices they imply, and the
// uplifting of an RGB reflectance to a smooth spectrum by the sigmoid polynomials of Jakob and Hanika 2019,
// "A Low-Dimensional Function Space for Efficient Spectral Upsampling" (EGSR), whose coefficient tables
// illum computes itself at build time (sigmoid_fit.h, tools/rgb2spec_opt.cpp, rgb_to_spectrum.h).
#pragma once

#include <cmath>
#include <string_view>

#include "illum/radiometry/color.h"
#include "illum/radiometry/spectra.h"

namespace illum {

// Every RGB <-> spectrum conversion here integrates over 360..830 nm (the CIE 1931 tables' range) by the
// trapezoid rule on a grid of kSpectralStepNm: ∫ f dλ ≈ h (f0/2 + f1 + ... + f_{n-1} + f_n/2). The white
// points, the illuminants' normalisation, the table generator and the round-trip tests share it, so a
// constant spectrum comes back as exactly that grey. 1 nm, not 5: on sRGB's uplifted spectra a 5 nm sum
// differs from a 1 nm one by up to 4.3e-4 in RGB, a 1 nm sum from a 0.25 nm one by 2e-5.
inline constexpr double kSpectrumMinNm = 360, kSpectrumMaxNm = 830;
inline constexpr double kSpectralStepNm = 1;

template <class F>
double integrate_spectrum(F&& f, double step_nm = kSpectralStepNm) {
    int n = int(std::lround((kSpectrumMaxNm - kSpectrumMinNm) / step_nm));
    double h = (kSpectrumMaxNm - kSpectrumMinNm) / n, sum = 0.5 * (f(kSpectrumMinNm) + f(kSpectrumMaxNm));
    for (int j = 1; j < n; ++j) sum += f(kSpectrumMinNm + j * h);
    return sum * h;
}

// Jakob & Hanika 2019, eqs. (3)-(4): s(λ) = S(c0 λ² + c1 λ + c2) with the sigmoid S(x) = 1/2 + x/(2√(1+x²)),
// λ in nm. c2 = ±∞ (with c0 = c1 = 0) is the constant 1 or 0 (white and black).
struct RGBSigmoidPolynomial {
    float c0 = 0, c1 = 0, c2 = 0;

    static float sigmoid(float x) {
        // Beyond 1e18 x² overflows (x/√(1+x²) would be 0 or NaN); S is 0 or 1 to float precision there.
        // Written as a select, so that a loop over wavelengths vectorises.
        float s = 0.5f + x / (2 * std::sqrt(1 + x * x));
        float limit = x > 0 ? 1.0f : 0.0f;
        return std::abs(x) < 1e18f ? s : limit;
    }
    float operator()(float lambda_nm) const {
        // Multiply-adds without std::fma: without hardware FMA in the build (no -march) each would be a libm
        // call, and the four wavelengths' evaluations (uplift.h) could not share vector instructions.
        return sigmoid((c0 * lambda_nm + c1) * lambda_nm + c2);
    }
    // S is increasing, so the maximum over 360..830 nm is at an end or, for c0 < 0, at the vertex
    // λ = -c1 / (2 c0) (Jakob & Hanika 2019 §3).
    float max_value() const;
};

class RGBColorSpace {
public:
    // "srgb", "rec2020", "aces2065-1", "dci-p3" (pbrt-v4's names); nullptr for any other name.
    static const RGBColorSpace* named(std::string_view name);
    static const RGBColorSpace& srgb();

    std::string_view name() const { return name_; }
    Chromaticity red() const { return r_; }
    Chromaticity green() const { return g_; }
    Chromaticity blue() const { return b_; }
    // XYZ of the white illuminant with Y = 1 (RGB (1, 1, 1)); its chromaticity is the white point.
    const double* white_xyz() const { return white_; }

    Color3 rgb_from_xyz(double X, double Y, double Z) const;
    void xyz_from_rgb(Color3 rgb, double xyz[3]) const;
    // Row-major 3x3, in float (the render loop's precision) and in double (what the conversions use).
    const float* rgb_from_xyz_matrix() const { return rgb_from_xyz_f_; }
    const float* xyz_from_rgb_matrix() const { return xyz_from_rgb_f_; }
    const double* rgb_from_xyz_matrix_f64() const { return rgb_from_xyz_; }
    const double* xyz_from_rgb_matrix_f64() const { return xyz_from_rgb_; }

    // The white illuminant's spectrum scaled to Y = 1: integrate_spectrum(I ȳ) = 1.
    double illuminant(double lambda_nm) const { return illuminant_(lambda_nm) * illuminant_scale_; }

    // The smooth reflectance spectrum of an RGB reflectance (clamped to [0, 1]): greys, black and white in
    // closed form, anything else trilinearly interpolated from this space's table (rgb_to_spectrum.h;
    // defined in rgb_to_spectrum.cpp, beside the embedded tables).
    RGBSigmoidPolynomial to_polynomial(Color3 rgb) const;

    // The index of this space among the four named ones (its table's index), 0..3.
    int index() const { return index_; }
    static constexpr int kCount = 4;
    static const RGBColorSpace& by_index(int i);

private:
    using Spectrum = double (*)(double lambda_nm);
    RGBColorSpace(std::string_view name, Chromaticity r, Chromaticity g, Chromaticity b, Spectrum illuminant,
                  int index);

    std::string_view name_;
    Chromaticity r_, g_, b_;
    Spectrum illuminant_;
    double illuminant_scale_ = 1;
    double white_[3] = {};
    double rgb_from_xyz_[9] = {}, xyz_from_rgb_[9] = {};
    float rgb_from_xyz_f_[9] = {}, xyz_from_rgb_f_[9] = {};
    int index_ = 0;
};

} // namespace illum
