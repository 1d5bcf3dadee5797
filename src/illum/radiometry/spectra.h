// Spectra: the CIE 1931 colour-matching functions and illuminants as the CIE tabulates them
// (cie_tables.h), Planck's law, spectra given as samples, and their reduction to XYZ and linear sRGB.
// The named spectra of pbrt-v4 scene files are in named_spectra.h (full spectra) and reduced to RGB
// once at scene build time by named_spectrum_rgb below; the CIE daylight series is in daylight.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "illum/radiometry/color.h"

namespace illum {

// CIE 1931 2° standard observer x̄, ȳ, z̄ (ISO/CIE 11664-1), tabulated at 1 nm from 360 to 830 nm,
// linearly interpolated between the samples and 0 outside [360, 830] nm.
double cie_x(double lambda_nm);
double cie_y(double lambda_nm);
double cie_z(double lambda_nm);

// Σ ȳ(λ) over the table's 1 nm samples, 360..830 nm: the Y of a constant spectrum 1 summed at 1 nm
// (pbrt-v4's CIE_Y_integral, 106.856895, is the same sum in single precision).
constexpr double kCieYIntegral = 106.85691710117;

// CIE standard illuminant D65 (ISO/CIE 11664-2), tabulated at 5 nm from 300 to 830 nm, normalised to 100
// at 560 nm, linearly interpolated (which reproduces the CIE's 1 nm table), 0 outside [300, 830] nm.
double cie_d65(double lambda_nm);

// CIE standard illuminant A, exactly as the CIE defines it (ISO/CIE 11664-2; CIE 015:2004):
// S_A(λ) = 100 (560/λ)^5 (exp(c2 / (560 T)) - 1) / (exp(c2 / (λ T)) - 1), λ in nm,
// c2 = 1.435e7 nm K, T = 2848 K: a Planckian radiator on the c2 scale of 1931, 100 at 560 nm.
double cie_illuminant_a(double lambda_nm);

// Planck's law: spectral radiance of a blackbody at temperature T [K] (W m^-2 sr^-1 m^-1), with
// pbrt-v4's constants (CODATA 2010): L(λ) = 2 h c² / (λ^5 (exp(h c / (λ k T)) - 1)). 0 for T <= 0.
double blackbody(double lambda_nm, double kelvin);
// pbrt-v4's "blackbody" spectrum: Planck's law divided by its value at the peak λ_max = b / T (Wien's
// displacement law, b = h c / (k x) with x = 4.965114231744276, the root of x = 5 (1 - e^-x)), so the
// maximum over λ is 1. 0 for T <= 0.
double blackbody_normalized(double lambda_nm, double kelvin);

// A spectrum given as samples (wavelength [nm], value), piecewise linear, constant beyond its ends.
struct PiecewiseLinearSpectrum {
    std::vector<double> lambda, value;
    double operator()(double lambda_nm) const;
};

// CIE XYZ tristimulus values and xy chromaticity.
struct Xyz {
    double x = 0, y = 0, z = 0;
};
struct Chromaticity {
    double x = 0, y = 0;
};
inline Chromaticity chromaticity(const Xyz& c) {
    double s = c.x + c.y + c.z;
    return s > 0 ? Chromaticity{c.x / s, c.y / s} : Chromaticity{};
}

// XYZ of a spectrum s(λ) as pbrt-v4 computes it (SpectrumToXYZ): Σ s(λ) (x̄, ȳ, z̄)(λ) over
// λ = 360, 361, ..., 830 nm, divided by kCieYIntegral, so that a spectrum of luminance 1 has Y = 1.
template <class Spectrum>
Xyz spectrum_to_xyz(const Spectrum& s) {
    Xyz r;
    for (int l = 360; l <= 830; ++l) {
        double v = s(double(l));
        r.x += v * cie_x(l);
        r.y += v * cie_y(l);
        r.z += v * cie_z(l);
    }
    return {r.x / kCieYIntegral, r.y / kCieYIntegral, r.z / kCieYIntegral};
}

// XYZ (D65 white) -> linear sRGB (IEC 61966-2-1).
Color3 xyz_to_linear_srgb(double x, double y, double z);

// A reflectance-like spectrum (reflectance, η, k) as RGB: XYZ of s·D65 normalised by Y of D65, then to
// linear sRGB, so a constant spectrum c gives (c, c, c).
Color3 unbounded_spectrum_to_rgb(const PiecewiseLinearSpectrum& s);
// An emission spectrum as RGB with its luminance normalised to 1, as pbrt-v4 does for light spectra
// ("radiance equivalent to 1 nit", scaled by the light's `scale`).
Color3 illuminant_spectrum_to_rgb(const PiecewiseLinearSpectrum& s);
Color3 blackbody_rgb(double kelvin); // luminance 1

// pbrt-v4's named spectra (named_spectra.h lists them) reduced to RGB (defined in named_spectra.cpp):
// metals "metal-<El>-eta"/"metal-<El>-k": the RGB indices fitted to the measured spectra
// (conductor_rgb.h); glasses "glass-BK7", ...: the Sellmeier index at 550 nm as a grey value (an RGB
// renderer cannot disperse); illuminants "stdillum-A", "stdillum-F4", "illum-acesD60", ...: the spectrum's
// RGB with luminance 1. Nothing for an unknown name.
std::optional<Color3> named_spectrum_rgb(const std::string& name);
// True for the named spectra that are illuminants (stdillum-*, illum-acesD60).
bool is_illuminant_name(const std::string& name);

} // namespace illum
