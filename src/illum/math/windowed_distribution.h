// A piecewise-constant density on [0, 1]² (an nu x nv grid of non-negative weights, row by row) sampled
// within any axis-aligned window [lo, hi] ⊂ [0, 1]², cells cut by the window counting with the part inside.
// What pbrt-v4's WindowedPiecewiseConstant2D does for the portal light, where the window is the portal seen
// from the receiving point. The integral over a window comes from a summed-area table (Crow, "Summed-area
// tables for texture mapping", SIGGRAPH 1984): G(x, y) = ∫₀ˣ∫₀ʸ f is bilinear within each cell, so
// interpolating the table is exact. A sample inverts the window's marginal CDF in y, then the conditional in
// x within the chosen row; both are piecewise linear, so the inversion is exact up to rounding.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

class WindowedDistribution2D {
public:
    WindowedDistribution2D() = default;
    // Negative and non-finite weights count as 0.
    WindowedDistribution2D(std::span<const float> weights, int nu, int nv);

    // A point of the window with density *pdf (per unit area of [0, 1]²) ∝ f; nullopt when the window holds
    // no weight. u.y picks the row, u.x the point within it.
    std::optional<Point2f> sample(Point2f u, Point2f lo, Point2f hi, float* pdf) const;
    // The density sample() gives p within the window [lo, hi]: f(p) / ∫_window f; 0 outside the window.
    float pdf(Point2f p, Point2f lo, Point2f hi) const;
    // ∫ f over the window.
    double integral(Point2f lo, Point2f hi) const;

    int size_u() const { return nu_; }
    int size_v() const { return nv_; }

private:
    // ∫₀ˣ∫₀ʸ f in cell units (each cell has area 1), x in [0, nu], y in [0, nv].
    double g(double x, double y) const;
    // ∫ from x0 to x of row j's f, in cell units.
    double row_prefix(int j, double x) const;
    float f(int i, int j) const { return f_[std::size_t(j) * std::size_t(nu_) + std::size_t(i)]; }
    double s(int i, int j) const { return sat_[std::size_t(j) * std::size_t(nu_ + 1) + std::size_t(i)]; }

    int nu_ = 0, nv_ = 0;
    std::vector<float> f_;
    std::vector<double> sat_; // (nu + 1) x (nv + 1): sat(i, j) = Σ_{x < i, y < j} f
};

} // namespace illum
