#include "illum/math/piecewise_bilinear_2d.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "illum/util/error.h"

namespace illum {

namespace {

// The largest i in [lo, hi] with pred(i) true, lo when none (pred is true then false along i).
template <class Pred>
int last_true(int lo, int hi, Pred pred) {
    while (lo < hi) {
        int mid = lo + (hi - lo + 1) / 2;
        if (pred(mid))
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

// t in [0, 1] with a t + (b - a) t²/2 = u, for the linear density (1-t) a + t b on [0, 1] whose integral
// up to t is u (u in [0, (a + b)/2]): the quadratic's root in the form without cancellation,
// t = 2u / (a + sqrt(a² + 2u (b - a))), which also holds for a = b.
float invert_linear(float a, float b, float u) {
    float denom = a + std::sqrt(std::max(0.0f, a * a + 2 * u * (b - a)));
    return denom > 0 ? std::clamp(2 * u / denom, 0.0f, 1.0f) : 0;
}

} // namespace

PiecewiseBilinear2D::PiecewiseBilinear2D(std::vector<float> data, int nx, int ny,
                                         std::vector<std::vector<float>> params, bool normalized)
    : nx_(nx), ny_(ny), normalized_(normalized), params_(std::move(params)), data_(std::move(data)) {
    if (nx < 2 || ny < 2) throw Error("a bilinear table needs at least 2 x 2 nodes");
    if (params_.size() > std::size_t(kMaxParams)) throw Error("a bilinear table has at most 3 parameters");
    std::size_t slices = 1;
    for (const auto& p : params_) {
        if (p.empty()) throw Error("a bilinear table's parameter has no nodes");
        for (std::size_t i = 1; i < p.size(); ++i)
            if (!(p[i] > p[i - 1])) throw Error("a bilinear table's parameter nodes must increase");
        slices *= p.size();
    }
    const std::size_t n = std::size_t(nx) * std::size_t(ny);
    if (data_.size() != slices * n)
        throw Error("a bilinear table holds " + std::to_string(data_.size()) + " values, not " +
                    std::to_string(slices * n));
    if (!normalized) return;

    cells_ = float(nx - 1) * float(ny - 1);
    conditional_.resize(slices * n);
    marginal_.resize(slices * std::size_t(ny));
    for (std::size_t s = 0; s < slices; ++s) {
        float* d = data_.data() + s * n;
        float* c = conditional_.data() + s * n;
        float* m = marginal_.data() + s * std::size_t(ny);
        for (std::size_t i = 0; i < n; ++i)
            if (!(d[i] >= 0) || !std::isfinite(d[i]))
                throw Error("a bilinear density must be finite and non-negative");
        double total = 0;
        for (int pass = 0; pass < 2; ++pass) {
            // Trapezoids in cell units: a row's running integral over x, then the rows' over y.
            for (int y = 0; y < ny; ++y) {
                double sum = 0;
                c[y * nx] = 0;
                for (int x = 0; x + 1 < nx; ++x) {
                    sum += 0.5 * (double(d[y * nx + x]) + double(d[y * nx + x + 1]));
                    c[y * nx + x + 1] = float(sum);
                }
            }
            double sum = 0;
            m[0] = 0;
            for (int y = 0; y + 1 < ny; ++y) {
                sum += 0.5 * (double(c[y * nx + nx - 1]) + double(c[(y + 1) * nx + nx - 1]));
                m[y + 1] = float(sum);
            }
            total = sum;
            if (total > 0 || pass == 1) break;
            std::fill(d, d + n, 1.0f); // a slice that is 0 everywhere: sampled uniformly
        }
        float norm = float(1 / total);
        for (std::size_t i = 0; i < n; ++i) {
            d[i] *= norm;
            c[i] *= norm;
        }
        for (int y = 0; y < ny; ++y) m[y] *= norm;
    }
}

PiecewiseBilinear2D::Blend PiecewiseBilinear2D::blend(const float* param) const {
    Blend b;
    b.slice[0] = 0;
    b.weight[0] = 1;
    b.count = 1;
    std::uint32_t stride = 1;
    for (int k = int(params_.size()) - 1; k >= 0; --k) {
        const std::vector<float>& v = params_[std::size_t(k)];
        const int n = int(v.size());
        if (n > 1) {
            float x = param[k];
            int i = last_true(0, n - 2, [&](int j) { return v[std::size_t(j)] <= x; });
            float t =
                std::clamp((x - v[std::size_t(i)]) / (v[std::size_t(i) + 1] - v[std::size_t(i)]), 0.0f, 1.0f);
            if (!(t == t)) t = 0; // NaN parameter
            for (int c = 0; c < b.count; ++c) {
                b.slice[std::size_t(c + b.count)] = b.slice[std::size_t(c)] + std::uint32_t(i + 1) * stride;
                b.weight[std::size_t(c + b.count)] = b.weight[std::size_t(c)] * t;
                b.slice[std::size_t(c)] += std::uint32_t(i) * stride;
                b.weight[std::size_t(c)] *= 1 - t;
            }
            b.count *= 2;
        }
        stride *= std::uint32_t(n);
    }
    return b;
}

float PiecewiseBilinear2D::evaluate(Point2f p, const float* param) const {
    Blend b = blend(param);
    float fx = std::clamp(p.x, 0.0f, 1.0f) * float(nx_ - 1),
          fy = std::clamp(p.y, 0.0f, 1.0f) * float(ny_ - 1);
    int x = std::min(int(fx), nx_ - 2), y = std::min(int(fy), ny_ - 2);
    float s = fx - float(x), t = fy - float(y);
    const std::size_t n = std::size_t(nx_) * std::size_t(ny_), i = std::size_t(y) * nx_ + std::size_t(x);
    float v00 = lookup(data_, n, i, b), v10 = lookup(data_, n, i + 1, b), v01 = lookup(data_, n, i + nx_, b),
          v11 = lookup(data_, n, i + nx_ + 1, b);
    return ((1 - t) * ((1 - s) * v00 + s * v10) + t * ((1 - s) * v01 + s * v11)) * cells_;
}

PiecewiseBilinear2D::Sample PiecewiseBilinear2D::sample(Point2f u, const float* param) const {
    Blend b = blend(param);
    const std::size_t n = std::size_t(nx_) * std::size_t(ny_), ny = std::size_t(ny_);
    const float lo = 1e-7f, hi = 1 - 1e-7f;
    u.x = std::clamp(u.x, lo, hi);
    u.y = std::clamp(u.y, lo, hi);

    // The row: the marginal CDF over y, then the linear density between the row integrals r0, r1.
    int row = last_true(0, ny_ - 2, [&](int j) { return lookup(marginal_, ny, std::size_t(j), b) <= u.y; });
    float uy = u.y - lookup(marginal_, ny, std::size_t(row), b);
    std::size_t r = std::size_t(row) * nx_;
    float r0 = lookup(conditional_, n, r + nx_ - 1, b), r1 = lookup(conditional_, n, r + 2 * nx_ - 1, b);
    float t = invert_linear(r0, r1, uy);

    // The column at height t: the conditional CDF blended between the rows, then the linear density.
    float ux = u.x * ((1 - t) * r0 + t * r1);
    auto cdf = [&](int x) {
        return (1 - t) * lookup(conditional_, n, r + std::size_t(x), b) +
               t * lookup(conditional_, n, r + nx_ + std::size_t(x), b);
    };
    int col = last_true(0, nx_ - 2, [&](int j) { return cdf(j) <= ux; });
    ux -= cdf(col);
    std::size_t i = r + std::size_t(col);
    float c0 = (1 - t) * lookup(data_, n, i, b) + t * lookup(data_, n, i + nx_, b),
          c1 = (1 - t) * lookup(data_, n, i + 1, b) + t * lookup(data_, n, i + nx_ + 1, b);
    float s = invert_linear(c0, c1, ux);
    return {Point2f((float(col) + s) / float(nx_ - 1), (float(row) + t) / float(ny_ - 1)),
            ((1 - s) * c0 + s * c1) * cells_};
}

PiecewiseBilinear2D::Sample PiecewiseBilinear2D::invert(Point2f p, const float* param) const {
    Blend b = blend(param);
    const std::size_t n = std::size_t(nx_) * std::size_t(ny_), ny = std::size_t(ny_);
    float fx = std::clamp(p.x, 0.0f, 1.0f) * float(nx_ - 1),
          fy = std::clamp(p.y, 0.0f, 1.0f) * float(ny_ - 1);
    int col = std::min(int(fx), nx_ - 2), row = std::min(int(fy), ny_ - 2);
    float s = fx - float(col), t = fy - float(row);
    std::size_t r = std::size_t(row) * nx_, i = r + std::size_t(col);
    float c0 = (1 - t) * lookup(data_, n, i, b) + t * lookup(data_, n, i + nx_, b),
          c1 = (1 - t) * lookup(data_, n, i + 1, b) + t * lookup(data_, n, i + nx_ + 1, b);
    float r0 = lookup(conditional_, n, r + nx_ - 1, b), r1 = lookup(conditional_, n, r + 2 * nx_ - 1, b);
    float row_integral = (1 - t) * r0 + t * r1;
    float x_cdf = (1 - t) * lookup(conditional_, n, i, b) + t * lookup(conditional_, n, i + nx_, b) + s * c0 +
                  0.5f * s * s * (c1 - c0);
    float ux = row_integral > 0 ? x_cdf / row_integral : 0;
    float uy = lookup(marginal_, ny, std::size_t(row), b) + t * r0 + 0.5f * t * t * (r1 - r0);
    return {Point2f(ux, uy), ((1 - s) * c0 + s * c1) * cells_};
}

} // namespace illum
