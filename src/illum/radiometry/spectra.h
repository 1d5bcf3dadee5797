// Spectra for an RGB renderer: the CIE 1931 colour matching functions, a spectrum -> linear sRGB
// conversion, and the named spectra of pbrt-v4 scene files (metal indices of refraction, glasses,
// standard illuminants, blackbodies), each reduced to RGB once at scene build time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "illum/radiometry/color.h"

namespace illum {

// CIE 1931 2° colour matching functions by the multi-lobe piecewise-Gaussian fit of Wyman, Sloan and
// Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2).
double cie_x(double lambda_nm);
double cie_y(double lambda_nm);
double cie_z(double lambda_nm);

// CIE standard illuminant D65 relative spectral power, tabulated at 10 nm from 380 to 780 nm (CIE 15),
// linearly interpolated, 0 outside.
double cie_d65(double lambda_nm);

// Planck's law: spectral radiance of a blackbody at temperature T [K] (W m^-2 sr^-1 m^-1).
double blackbody(double lambda_nm, double kelvin);

// A spectrum given as samples (wavelength [nm], value), piecewise linear, constant beyond its ends.
struct PiecewiseLinearSpectrum {
    std::vector<double> lambda, value;
    double operator()(double lambda_nm) const;
};

// XYZ (D65 white) -> linear sRGB (IEC 61966-2-1).
Color3 xyz_to_linear_srgb(double x, double y, double z);

// A reflectance-like spectrum (reflectance, η, k) as RGB: XYZ of s·D65 normalised by Y of D65, then to
// linear sRGB, so a constant spectrum c gives (c, c, c).
Color3 unbounded_spectrum_to_rgb(const PiecewiseLinearSpectrum& s);
// An emission spectrum as RGB with its luminance normalised to 1, as pbrt-v4 does for light spectra
// ("radiance equivalent to 1 nit", scaled by the light's `scale`).
Color3 illuminant_spectrum_to_rgb(const PiecewiseLinearSpectrum& s);
Color3 blackbody_rgb(double kelvin); // luminance 1

// pbrt-v4's named spectra. Metals: "metal-<El>-eta"/"metal-<El>-k" for Ag, Al, Au, Cu, CuZn, MgO, TiO2,
// RGB indices fitted to the measured spectra (metal_spectra.h, conductor_rgb.h); glasses "glass-BK7", ...
// (the index at 550 nm, as a grey value); "stdillum-D65", "stdillum-A"... (luminance 1). Returns nothing for
// an unknown name.
std::optional<Color3> named_spectrum_rgb(const std::string& name);
bool is_illuminant_name(const std::string& name);

} // namespace illum
