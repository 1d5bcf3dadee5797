// Spherical harmonics up to order 2 for irradiance environment maps (R. Ramamoorthi and P. Hanrahan,
// "An Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001).
//
// The real basis of the paper (eq. 3), with (x, y, z) a unit direction in the map's frame (+z up):
//   Y00 = 0.282095;  Y1-1 = 0.488603 y,  Y10 = 0.488603 z,  Y11 = 0.488603 x;
//   Y2-2 = 1.092548 xy,  Y2-1 = 1.092548 yz,  Y21 = 1.092548 xz,  Y20 = 0.315392 (3z² - 1),
//   Y22 = 0.546274 (x² - y²).
// Radiance coefficients L_lm = ∫ L(ω) Y_lm(ω) dω, by exact per-texel solid angles; irradiance
// E(n) = Σ Â_l L_lm Y_lm(n) with the clamped-cosine convolution constants Â0 = π, Â1 = 2π/3, Â2 = π/4.
#pragma once

#include <array>
#include <string>

#include "illum/envmap/environment_map.h"

namespace illum {

// Order of the nine coefficients: L00, L1m1, L10, L11, L2m2, L2m1, L20, L21, L22.
inline constexpr std::array<const char*, 9> kSHNames{"L00",  "L1m1", "L10", "L11", "L2m2",
                                                     "L2m1", "L20",  "L21", "L22"};
// The band l of coefficient i.
constexpr int sh_band(int i) { return i == 0 ? 0 : (i < 4 ? 1 : 2); }

std::array<double, 9> sh_basis(Vector3f d);

struct SH9 {
    std::array<std::array<double, 3>, 9> c{}; // c[i][channel]

    // The irradiance at normal n: Σ Â_l L_lm Y_lm(n).
    Color3 irradiance(Vector3f n) const;
    // The radiance of the order-2 reconstruction: Σ L_lm Y_lm(d).
    Color3 radiance(Vector3f d) const;
};

// Projects the map's radiance: Σ over texels of L Y(ω_centre) Ω_texel.
SH9 project_sh(const EnvironmentMap& map);

// The irradiance environment map E(n) of the coefficients, in a layout and size.
EnvironmentMap sh_irradiance_map(const SH9& sh, EnvLayout layout, int height);

// {"L00": [r, g, b], ...} with the names above.
std::string sh_to_json(const SH9& sh);

} // namespace illum
