// Directional albedo ρ(wo) = ∫ f(wo, wi) |cos θi| dωi over the whole sphere (reflection + transmission),
// by deterministic quadrature of f and by Monte Carlo with the model's own sampling (with standard
// error). Double precision throughout. Evaluated in importance mode, where it is the fraction of the
// power arriving from wo that the surface scatters (energy conservation means <= 1).
#pragma once

#include <array>
#include <cstdint>

#include "illum/bsdf/bxdf.h"

namespace illum {

using Rgb64 = std::array<double, 3>;

struct AlbedoEstimate {
    bool has_quadrature = false; // false for delta models (f() is 0)
    Rgb64 quadrature{};
    Rgb64 mc{}, mc_stderr{};
    int mc_samples = 0;
};

// Quadrature: midpoint rule in (θ, φ) with the sin θ Jacobian, n_theta x 2 n_theta points per
// hemisphere (the hemisphere of wo only when `reflection_only`).
Rgb64 albedo_quadrature(const BxDF& bxdf, Vector3f wo, int n_theta, bool reflection_only,
                        TransportMode mode = TransportMode::Importance);
// Monte Carlo with sample(): mean weight f |cos| / pdf (0 for failed samples) and its standard error;
// optionally also the part carried by non-delta samples (what f() describes).
void albedo_monte_carlo(const BxDF& bxdf, Vector3f wo, int samples, std::uint64_t seed, Rgb64* mean,
                        Rgb64* stderr_, TransportMode mode = TransportMode::Importance,
                        Rgb64* nonspecular_mean = nullptr, Rgb64* nonspecular_stderr = nullptr);

AlbedoEstimate directional_albedo(const BxDF& bxdf, Vector3f wo, bool delta, int n_theta, int mc_samples,
                                  std::uint64_t seed);

// Direction from angles in degrees (θ from +z, φ from +x).
Vector3f direction_deg(double theta_deg, double phi_deg);

} // namespace illum
