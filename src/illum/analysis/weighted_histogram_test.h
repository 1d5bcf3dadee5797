// A sampling test for stochastic BSDFs, whose f() is an unbiased estimate and whose pdf() is only an
// approximation (layered models), so that the chi-square test of sample() against pdf() does not apply.
// What must hold instead is that sample() spreads its weights f|cos θ|/pdf over the directions as f()
// says. Per bin b of an equal-solid-angle (cos θ, φ) grid over wo's hemisphere:
//   A_b = (1/N) Σ_i w_i [ω_i ∈ b]                (N calls of sample(); delta samples excluded),
//   B_b = (Ω_b / M) Σ_j f(wo, ω_j) |cos θ_j|      (M jittered-stratified directions ω_j in b),
// both unbiased for ∫_b f |cos θ| dω. With their variances estimated from the same sums (the stratified
// one conservatively, as if independent), z_b = (A_b - B_b) / sqrt(Var A_b + Var B_b) is approximately
// standard normal, and Σ z_b² approximately chi-square with one degree of freedom per bin. Bins that fewer
// than `min_hits` samples reached are pooled into one, so that the normal approximation holds.
#pragma once

#include <cstdint>
#include <string>

#include "illum/bsdf/bxdf.h"

namespace illum {

struct WeightedHistogramResult {
    double statistic = 0, p_value = 1;
    int dof = 0;
    double worst_z = 0; // the bin with the largest |z|
    std::string detail;
};

WeightedHistogramResult weighted_histogram_test(const BxDF& bxdf, Vector3f wo, TransportMode mode,
                                                int samples, int cos_bins, int phi_bins, int f_per_bin,
                                                std::uint64_t seed, int min_hits = 50);

} // namespace illum
