#include "illum/math/distribution.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f; // largest float below 1

float sanitize(float w) { return (w > 0 && std::isfinite(w)) ? w : 0.0f; }

float clamp_unit(float u) { return std::clamp(u, 0.0f, kOneMinusEpsilon); }

int piece_of(float x, int n) { return std::clamp(int(double(x) * n), 0, n - 1); }

} // namespace

// ---------------------------------------------------------------------------------------------------------
// Distribution1D

Distribution1D::Distribution1D(std::span<const float> weights)
    : func_(weights.size()), cdf_(weights.size() + 1) {
    const size_t n = weights.size();
    if (n == 0) return;
    double sum = 0;
    cdf_[0] = 0;
    for (size_t i = 0; i < n; ++i) {
        func_[i] = sanitize(weights[i]);
        sum += func_[i];
        cdf_[i + 1] = sum;
    }
    integral_ = sum / double(n);
    degenerate_ = !(sum > 0) || !std::isfinite(sum);
    if (degenerate_) {
        for (size_t i = 1; i <= n; ++i) cdf_[i] = double(i) / double(n);
    } else {
        for (size_t i = 1; i <= n; ++i) cdf_[i] /= sum;
    }
    cdf_[n] = 1;
}

int Distribution1D::find_interval(double u) const {
    // The first entry with cdf > u, minus one: skips zero-width (zero-weight) pieces, and since
    // cdf_[0] = 0 <= u < 1 = cdf_[n] the result is in [0, n - 1].
    auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    return std::clamp(int(it - cdf_.begin()) - 1, 0, size() - 1);
}

float Distribution1D::sample_continuous(float u, float* pdf, int* offset) const {
    const int n = size();
    const double uc = clamp_unit(u);
    const int i = find_interval(uc);
    const double lo = cdf_[size_t(i)], hi = cdf_[size_t(i) + 1];
    const double du = hi > lo ? (uc - lo) / (hi - lo) : 0.0;
    float x = float((double(i) + du) / double(n));
    // Rounding to float may put x on a neighbouring piece; step it back so that pdf(x) is this piece's.
    if (piece_of(x, n) > i) x = std::nextafter(x, 0.0f);
    if (piece_of(x, n) < i) x = std::nextafter(x, 1.0f);
    x = std::min(x, kOneMinusEpsilon);
    if (pdf) *pdf = degenerate_ ? 1.0f : float(double(func_[size_t(i)]) / integral_);
    if (offset) *offset = i;
    return x;
}

int Distribution1D::sample_discrete(float u, float* pmf, float* u_remapped) const {
    const double uc = clamp_unit(u);
    const int i = find_interval(uc);
    const double lo = cdf_[size_t(i)], hi = cdf_[size_t(i) + 1];
    if (pmf) *pmf = float(hi - lo);
    if (u_remapped) *u_remapped = std::min(float(hi > lo ? (uc - lo) / (hi - lo) : 0.0), kOneMinusEpsilon);
    return i;
}

float Distribution1D::pdf(float x) const {
    if (func_.empty()) return 0;
    if (degenerate_) return 1;
    return float(double(func_[size_t(piece_of(x, size()))]) / integral_);
}

float Distribution1D::pmf(int i) const {
    if (i < 0 || i >= size()) return 0;
    return float(cdf_[size_t(i) + 1] - cdf_[size_t(i)]);
}

// ---------------------------------------------------------------------------------------------------------
// Distribution2D

Distribution2D::Distribution2D(std::span<const float> weights, int nu, int nv) : nu_(nu), nv_(nv) {
    if (nu <= 0 || nv <= 0 || weights.size() < size_t(nu) * size_t(nv)) {
        nu_ = nv_ = 0;
        return;
    }
    conditional_.reserve(size_t(nv));
    std::vector<float> row_integrals(static_cast<size_t>(nv));
    for (int v = 0; v < nv; ++v) {
        conditional_.emplace_back(weights.subspan(size_t(v) * size_t(nu), size_t(nu)));
        row_integrals[size_t(v)] = conditional_.back().integral();
    }
    marginal_ = Distribution1D(row_integrals);
}

Point2f Distribution2D::sample(Point2f u, float* pdf) const {
    if (nu_ == 0) {
        if (pdf) *pdf = 0;
        return {};
    }
    float pdf_v, pdf_u;
    int v;
    float y = marginal_.sample_continuous(u[1], &pdf_v, &v);
    float x = conditional_[size_t(v)].sample_continuous(u[0], &pdf_u);
    if (pdf) *pdf = pdf_u * pdf_v;
    return {x, y};
}

float Distribution2D::pdf(Point2f p) const {
    if (nu_ == 0) return 0;
    if (marginal_.is_degenerate()) return 1;
    int iu = piece_of(p.x, nu_), iv = piece_of(p.y, nv_);
    return conditional_[size_t(iv)].func(iu) / marginal_.integral();
}

// ---------------------------------------------------------------------------------------------------------
// AliasTable

AliasTable::AliasTable(std::span<const float> weights) : bins_(weights.size()) {
    const size_t n = weights.size();
    if (n == 0) return;
    double sum = 0;
    for (float w : weights) sum += sanitize(w);
    degenerate_ = !(sum > 0) || !std::isfinite(sum);
    if (degenerate_) {
        for (size_t i = 0; i < n; ++i) bins_[i] = {1.0f, float(1.0 / double(n)), uint32_t(i)};
        return;
    }

    // Vose: scale the probabilities by n so the mean is 1; repeatedly pair an outcome below 1 (small)
    // with one at or above 1 (large), which fills the small one's bin and loses that much.
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    small.reserve(n);
    large.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        double p = double(sanitize(weights[i])) / sum;
        bins_[i].p = float(p);
        bins_[i].alias = uint32_t(i);
        scaled[i] = p * double(n);
        (scaled[i] < 1 ? small : large).push_back(uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
        uint32_t l = small.back(), g = large.back();
        small.pop_back();
        large.pop_back();
        bins_[l].q = float(scaled[l]);
        bins_[l].alias = g;
        scaled[g] = (scaled[g] + scaled[l]) - 1; // this order of operations is the numerically stable one
        (scaled[g] < 1 ? small : large).push_back(g);
    }
    // What is left is within rounding of 1.
    for (uint32_t g : large) bins_[g].q = 1;
    for (uint32_t l : small) bins_[l].q = bins_[l].p > 0 ? 1.0f : 0.0f;
}

} // namespace illum
