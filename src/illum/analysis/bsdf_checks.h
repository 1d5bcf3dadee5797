// The BSDF audits (audit.h) as checks: every registered model over its parameter grid, with the chi-square
// family of the whole run corrected by Sidak as `illum brdf audit all` does. Three checks per model:
//   energy       ρ(θo) = ∫ f |cos θi| dωi <= 1 by Monte Carlo with the model's sampling (= 1 for the
//                lossless cases), the largest albedo shown: fails above 1 + 4σ + 10⁻³;
//   reciprocity  f(wo, wi) = f(wi, wo) (generalised with η² and the adjoint for transmission), the worst
//                relative difference over 1000 pairs shown: fails above 5·10⁻³ (a stochastic model: its
//                mean difference beyond 4.5σ);
//   sampling     positivity, sample() against f() and pdf(), the quadrature of f against the Monte Carlo
//                albedo, the chi-square test of sample() against pdf() at 1% family-wise; the count of
//                failed audits shown.
// A non-physical model (toon) has its energy and reciprocity reported, not required.
#pragma once

#include <string>
#include <vector>

#include "illum/analysis/audit.h"
#include "illum/analysis/verify_check.h"

namespace illum {

std::vector<VerifyCheck> check_bsdf_audits(const VerifyOptions& options);

// One BxDF's energy and reciprocity audits as checks (for a BxDF outside the registry, as in a test).
VerifyCheck check_bxdf_energy(const BxDF& bxdf, const std::string& name, const AuditTraits& traits,
                              const VerifyOptions& options);
VerifyCheck check_bxdf_reciprocity(const BxDF& bxdf, const std::string& name, const AuditTraits& traits,
                                   const VerifyOptions& options);

} // namespace illum
