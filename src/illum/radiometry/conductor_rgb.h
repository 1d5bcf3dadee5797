// RGB stand-ins for a measured complex index η(λ) + i k(λ) (metal_spectra.h), for an RGB renderer
// that evaluates the exact conductor Fresnel equations per channel.
//
// Two reductions:
//  - integrated_index_rgb: η(λ) and k(λ) each reduced like a reflectance (XYZ under D65 -> linear
//    sRGB, unbounded_spectrum_to_rgb). Simple, but Fresnel is not linear in η, k, so
//    F(RGB η, RGB k) is not the RGB of the spectral reflectance F(η(λ), k(λ)).
//  - fitted_index_rgb: per channel, the (η, k) whose Fresnel curve reproduces the RGB of the
//    spectral reflectance: exact at normal incidence, least squares over incidence angles, with η kept
//    within the measured visible range of η(λ) and k below its maximum. Used for the named spectra:
//    worst error 0.008 against 0.017 for the integrated reduction (docs/verification.md).
// The reference both are measured against is reflectance_rgb: the RGB (under D65) of the spectral
// Fresnel reflectance at one angle, which is what a spectral renderer (pbrt-v4) shows for one
// bounce of white (D65) light.
#pragma once

#include "illum/radiometry/color.h"
#include "illum/radiometry/metal_spectra.h"

namespace illum {

struct ConductorRgb {
    Color3 eta, k;
};

// Exact unpolarised Fresnel reflectance of a conductor η + i k seen from vacuum, in double precision
// (Born & Wolf, "Principles of Optics", §1.5.2 and §14.2): with the complex index n = η + i k,
// cos θt = sqrt(1 - sin²θ / n²), r_s = (cos θ - n cos θt)/(cos θ + n cos θt),
// r_p = (n cos θ - cos θt)/(n cos θ + cos θt), F = (|r_s|² + |r_p|²)/2.
// Independent of bsdf/fresnel.h (a different formulation), so each checks the other.
double fresnel_conductor_exact(double cos_theta, double eta, double k);

// RGB (D65, linear sRGB) of the spectral reflectance F(θ; η(λ), k(λ)).
Color3 reflectance_rgb(const MeasuredIndex& m, double cos_theta);

ConductorRgb integrated_index_rgb(const MeasuredIndex& m);
ConductorRgb fitted_index_rgb(const MeasuredIndex& m);

// fitted_index_rgb, the reduction illum uses for the named spectra "metal-<El>-eta"/"metal-<El>-k", computed
// once per element on first use. Nullptr for an element that is not tabulated.
const ConductorRgb* named_conductor_rgb(std::string_view element);

} // namespace illum
