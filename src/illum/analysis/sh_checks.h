// Spherical-harmonic irradiance (Ramamoorthi & Hanrahan 2001) and the brute-force convolution against
// closed forms, on maps made in memory (latitude-longitude, 512 x 256):
//   - radiance within order 2, L = 1 + z + xy: both give E(n) = π + (2π/3) n_z + (π/4) n_x n_y exactly
//     (Funk-Hecke with Â0 = π, Â1 = 2π/3, Â2 = π/4);
//   - a small sun (radius 1.5°, radiance L; its solid angle Ω and direction s summed over its texels):
//     the brute force gives E = L Ω cos γ at γ from the sun; the nine coefficients give, by the addition
//     theorem
//     Σ_m Y_lm(s) Y_lm(n) = (2l + 1)/(4π) P_l(cos γ),
//       E_SH = L Ω [1/4 + cos γ / 2 + (5/16) P2(cos γ)],  P2(x) = (3x² - 1)/2,
//     17/16 of the truth towards the sun: the truncation's known excess.
// Deterministic (quadrature): the tolerance is a relative allowance for the finite texels.
#pragma once

#include <vector>

#include "illum/analysis/verify_check.h"

namespace illum {

std::vector<VerifyCheck> check_sh_irradiance(const VerifyOptions& options);

} // namespace illum
