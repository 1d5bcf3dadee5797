// The radiometry of the course as checks of the renderer's own code (DESIGN.md §4.3): each renders a small
// scene with the real parser, shapes, lights, integrators and render loop, and compares its pixels'
// mean with the closed form.
//   - Irradiance on the axis of a uniform disk of radius r at height h: E = π L sin²α = π L r²/(r² + h²).
//   - The rule of five: a disk of diameter D seen from h >= 5 D is a point source of intensity
//     I = L π r² within 1%, since E_disk/E_point = h²/(r² + h²) = 1/(1 + (r/h)²) and (r/h)² <= 1/100;
//     and the point source itself obeys the inverse-square law, E = I/h² on its axis.
//   - A closed furnace (a sphere that emits Le and reflects with Lambertian albedo ρ, seen from inside):
//     L = Le Σ ρ^k = Le/(1 - ρ), by the path tracer with Russian roulette to depth 1000 (unbounded for
//     ρ <= 0.8: the truncation is ρ^1000 < 10⁻⁹⁶; a BSDF that gains energy cannot hang the check).
//   - Radiance is invariant along a ray: a uniform emitter looks equally bright from any distance.
//   - A Lambertian plane of albedo ρ under a uniform environment of radiance L: L_o = ρ L.
// The furnace and the plane take the Lambertian BSDF to test (the renderer's LambertBxDF unless told
// otherwise), so a test can hand them a broken one and see them fail.
#pragma once

#include <functional>
#include <vector>

#include "illum/analysis/verify_check.h"
#include "illum/bsdf/bxdf.h"
#include "illum/util/arena.h"

namespace illum {

// A Lambertian reflector of albedo ρ, placed in the per-thread arena at each hit.
using LambertMaker = std::function<const BxDF*(SampledSpectrum reflectance, ScratchArena& arena)>;
const BxDF* renderer_lambert(SampledSpectrum reflectance, ScratchArena& arena);

std::vector<VerifyCheck> check_disk_irradiance(const VerifyOptions& options);
std::vector<VerifyCheck> check_rule_of_five(const VerifyOptions& options);
VerifyCheck check_closed_furnace(double rho, double le, const VerifyOptions& options,
                                 const LambertMaker& lambert = renderer_lambert);
std::vector<VerifyCheck> check_radiance_invariance(const VerifyOptions& options);
VerifyCheck check_lambertian_plane(double rho, const VerifyOptions& options,
                                   const LambertMaker& lambert = renderer_lambert);

} // namespace illum
