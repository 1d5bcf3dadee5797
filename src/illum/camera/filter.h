// Pixel reconstruction filters, sampled rather than splatted: each camera sample is offset from its
// pixel's center with density proportional to |f| and weighted by f/pdf (1 for the positive filters
// sampled exactly, ±∫|f| for the tabulated ones with negative lobes), so a sample contributes to its own
// pixel only and the image is independent of tile order and thread count (filter importance sampling; Ernst
// et al. 2006, as in pbrt-v4).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "illum/math/distribution.h"
#include "illum/math/vector.h"

namespace illum {

struct FilterSample {
    Vector2f offset; // from the pixel center, in pixels
    float weight = 1;
};

class Filter {
public:
    explicit Filter(Vector2f radius) : radius_(radius) {}
    virtual ~Filter() = default;
    Vector2f radius() const { return radius_; }
    virtual float evaluate(Vector2f p) const = 0;
    virtual FilterSample sample(Point2f u) const = 0;

protected:
    Vector2f radius_;
};

class BoxFilter final : public Filter {
public:
    explicit BoxFilter(Vector2f radius = {0.5f, 0.5f}) : Filter(radius) {}
    float evaluate(Vector2f p) const override {
        return (std::abs(p.x) <= radius_.x && std::abs(p.y) <= radius_.y) ? 1.0f : 0.0f;
    }
    FilterSample sample(Point2f u) const override {
        return {{(2 * u.x - 1) * radius_.x, (2 * u.y - 1) * radius_.y}, 1};
    }
};

// The tent max(0, 1 - |x|/r) in each axis.
class TriangleFilter final : public Filter {
public:
    explicit TriangleFilter(Vector2f radius = {2, 2}) : Filter(radius) {}
    float evaluate(Vector2f p) const override {
        return std::max(0.0f, radius_.x - std::abs(p.x)) * std::max(0.0f, radius_.y - std::abs(p.y));
    }
    FilterSample sample(Point2f u) const override {
        return {{sample_tent(u.x) * radius_.x, sample_tent(u.y) * radius_.y}, 1};
    }
    // Inverse CDF of the unit tent on [-1, 1].
    static float sample_tent(float u) {
        if (u < 0.5f) return -1 + std::sqrt(2 * u);
        return 1 - std::sqrt(2 - 2 * u);
    }
};

// pbrt-v4's Gaussian: g(x) - g(r) per axis, g(x) = exp(-x²/(2σ²)) / sqrt(2πσ²), zero beyond r.
// Sampled exactly by inverting its CDF (Newton's method on the erf-based closed form).
class GaussianFilter final : public Filter {
public:
    explicit GaussianFilter(Vector2f radius = {1.5f, 1.5f}, float sigma = 0.5f);
    float evaluate(Vector2f p) const override;
    FilterSample sample(Point2f u) const override;
    float sigma() const { return sigma_; }

private:
    // The exact inverse of the axis' CDF at u (Newton's method with bisection from x = 0: slow, used to
    // build the table), and the same from the table's guess, refined by Newton's method (usually one
    // step; a sixth of a path tracer's time on small scenes went to the slow one).
    double invert_cdf(double u, int axis) const;
    float sample_axis(float u, int axis) const;
    float sigma_;
    static constexpr int kTableSize = 1024;
    std::array<std::array<float, kTableSize + 1>, 2> inverse_cdf_{}; // x at u = k / kTableSize
    // Per axis: ∫ (g - g(r)) over [-r, r], g(r), erf(-r / σ√2); and g(0).
    std::array<double, 2> total_{}, g_edge_{}, erf_low_{};
    double g_peak_ = 0;
};

// Filters with negative lobes, sampled as pbrt-v4's FilterSampler does: f tabulated at the centres of 32
// cells per unit of radius in each axis, a piecewise-constant density ∝ |f| over the cells, and the weight
// f(cell) / pdf (so ±∫|f| up to the table's resolution). A subclass calls tabulate() once constructed.
class TabulatedFilter : public Filter {
public:
    using Filter::Filter;
    FilterSample sample(Point2f u) const override;

protected:
    void tabulate();

private:
    int nx_ = 0, ny_ = 0;
    std::vector<float> f_;
    Distribution2D distribution_;
};

// Mitchell & Netravali 1988, "Reconstruction Filters in Computer Graphics": the cubic k(x) with parameters
// B, C on |x| < 2, per axis at 2x/r (pbrt-v4's "mitchell": radius 2, B = C = 1/3).
class MitchellFilter final : public TabulatedFilter {
public:
    MitchellFilter(Vector2f radius = {2, 2}, float b = 1.0f / 3, float c = 1.0f / 3);
    float evaluate(Vector2f p) const override;
    static float mitchell_1d(float x, float b, float c);

private:
    float b_, c_;
};

// The Lanczos-windowed sinc, sinc(x) sinc(x/τ) for |x| <= r per axis, sinc(x) = sin(πx)/(πx)
// (pbrt-v4's "sinc": radius 4, tau 3).
class LanczosSincFilter final : public TabulatedFilter {
public:
    explicit LanczosSincFilter(Vector2f radius = {4, 4}, float tau = 3);
    float evaluate(Vector2f p) const override;

private:
    float tau_;
};

// Makes a filter by pbrt-v4 name ("box", "triangle", "gaussian"); radius <= 0 takes the default.
std::unique_ptr<Filter> make_filter(const std::string& name, Vector2f radius, float sigma = 0.5f);

} // namespace illum
