// Tabulated distributions: piecewise-constant 1D and 2D densities sampled by inverting the CDF, and an
// alias table for O(1) discrete sampling. Construction allocates; sampling and evaluation do not.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

// Piecewise-constant density on [0, 1) with n equal pieces whose heights are proportional to the weights.
// Weights must be finite and non-negative; negative and NaN weights are treated as 0. If every weight is 0
// the distribution falls back to uniform and is_degenerate() is true (integral() still reports 0).
//
// The CDF is kept in double: with millions of pieces (environment maps) a float CDF rounds small pieces
// to zero width or makes neighbouring entries equal, and the sampled density would no longer match pdf().
class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(std::span<const float> weights);

    // Continuous sample x in [0, 1) with density *pdf = weight[i] / integral(); *offset is the piece i.
    float sample_continuous(float u, float* pdf = nullptr, int* offset = nullptr) const;
    // Discrete sample i with probability *pmf = weight[i] / sum; *u_remapped is u's position within the
    // piece's CDF interval, uniform in [0, 1) and independent of i, so it can be reused.
    int sample_discrete(float u, float* pmf = nullptr, float* u_remapped = nullptr) const;

    // Density at x in [0, 1) (x outside is clamped to the first or last piece).
    float pdf(float x) const;
    // Probability of piece i.
    float pmf(int i) const;
    // Mean of the weights, i.e. the integral of the piecewise-constant function over [0, 1).
    float integral() const { return float(integral_); }
    int size() const { return int(func_.size()); }
    bool is_degenerate() const { return degenerate_; }
    // The (sanitised) weight of piece i.
    float func(int i) const { return func_[size_t(i)]; }

private:
    // Index i with cdf_[i] <= u < cdf_[i + 1] and a non-empty interval.
    int find_interval(double u) const;

    std::vector<float> func_;
    std::vector<double> cdf_; // size n + 1, cdf_[0] = 0, cdf_[n] = 1
    double integral_ = 0;
    bool degenerate_ = true;
};

// Piecewise-constant density on [0, 1)^2 over an nu x nv grid of weights stored row by row
// (weights[v * nu + u]): a marginal distribution picks the row v, then that row's conditional picks u.
// x runs along a row, y across rows. All-zero input gives the uniform density.
class Distribution2D {
public:
    Distribution2D() = default;
    Distribution2D(std::span<const float> weights, int nu, int nv);

    // Sample with density *pdf with respect to area on [0, 1)^2. u[0] picks within the row, u[1] the row.
    Point2f sample(Point2f u, float* pdf = nullptr) const;
    float pdf(Point2f p) const;

    int size_u() const { return nu_; }
    int size_v() const { return nv_; }
    float integral() const { return marginal_.integral(); }
    bool is_degenerate() const { return marginal_.is_degenerate(); }

private:
    int nu_ = 0, nv_ = 0;
    std::vector<Distribution1D> conditional_;
    Distribution1D marginal_;
};

// Alias table for sampling n outcomes in O(1) (A. J. Walker 1977; the stable linear-time construction of
// M. D. Vose, "A Linear Algorithm for Generating Random Numbers with a Given Distribution", IEEE TSE 1991).
// Same weight rules as Distribution1D.
class AliasTable {
public:
    AliasTable() = default;
    explicit AliasTable(std::span<const float> weights);

    // Outcome i with probability *pmf; *u_remapped is uniform in [0, 1) and independent of the outcome.
    // (Inline: next-event estimation picks a light with it at every vertex.)
    int sample(float u, float* pmf = nullptr, float* u_remapped = nullptr) const;
    float pmf(int i) const { return bins_[size_t(i)].p; }
    int size() const { return int(bins_.size()); }
    bool is_degenerate() const { return degenerate_; }

private:
    static constexpr float kBelowOne = 0x1.fffffep-1f; // the largest float below 1
    struct Bin {
        float q = 1;        // probability of keeping the bin's own outcome
        float p = 0;        // the outcome's probability
        uint32_t alias = 0; // the other outcome sharing this bin
    };
    std::vector<Bin> bins_;
    bool degenerate_ = true;
};

inline int AliasTable::sample(float u, float* pmf, float* u_remapped) const {
    const int n = size();
    if (n == 0) {
        if (pmf) *pmf = 0;
        return 0;
    }
    const double un = double(std::clamp(u, 0.0f, kBelowOne)) * n;
    const int i = std::min(int(un), n - 1);
    const double up = un - i;
    const Bin& b = bins_[size_t(i)];
    const bool own = up < b.q;
    const int out = own ? i : int(b.alias);
    if (pmf) *pmf = bins_[size_t(out)].p;
    // (The divisions only when asked: picking a light needs none.)
    if (u_remapped) *u_remapped = std::min(float(own ? up / b.q : (up - b.q) / (1.0 - b.q)), kBelowOne);
    return out;
}

} // namespace illum
