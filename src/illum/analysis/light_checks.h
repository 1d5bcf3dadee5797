// The power of every light type, two ways against its closed form Φ: the mean flux of the photons its
// sample_le emits (E[flux] = Φ, the estimator light tracing, photon mapping and BDPT rely on), and its
// power() (what light selection by power uses). The lights are the renderer's own, made from pbrt-v4
// scene text by the light factory (the image environment from a map in memory):
//   point           Φ = 4π I                                  spot  Φ = 2π I [(1 - cos θs) + (cos θs - cos
//   θe)/2] distant         Φ = π r² E        (r: the scene's bounding sphere, which its photons cover) area
//   (diffuse)  Φ = π L A, twice that two-sided           uniform infinite  Φ = 4π · π r² L image infinite  Φ
//   = s π r² Σ L_texel Ω_texel, Ω = Δφ (cos θ0 - cos θ1) for a latitude-longitude texel
//   goniometric  Φ = 4π I mean(Y)    projection (constant image)  Φ = s L · the frustum's solid angle
//   image area (disk, image along φ)  Φ = π A s mean(L)          portal (uniform sky)  Φ = π A L
#pragma once

#include <string>
#include <vector>

#include "illum/analysis/verify_check.h"
#include "illum/light/light.h"

namespace illum {

// The photons' mean flux against `expected` (RGB, watts), per channel (the worst reported); `allowance`
// is ε of the tolerance rule (verify_check.h).
VerifyCheck check_light_power(const Light& light, const std::string& name, const std::string& closed_form,
                              Color3 expected, int photons, const VerifyOptions& options,
                              double allowance = 1e-4);
// power() against `expected`, to float rounding (or `allowance` of it, for a power() found by quadrature).
VerifyCheck check_light_power_method(const Light& light, const std::string& name,
                                     const std::string& closed_form, Color3 expected,
                                     const VerifyOptions& options, double allowance = 1e-4);

std::vector<VerifyCheck> check_light_powers(const VerifyOptions& options);

} // namespace illum
