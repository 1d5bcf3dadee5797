// A function on the unit square given at the nodes of a regular nx x ny grid and interpolated
// bilinearly, optionally conditioned on up to three parameters (each with its own grid of values; the
// slices at the surrounding parameter nodes are blended multilinearly). As a density (`normalized`), it
// is scaled to integrate to 1 over [0, 1]^2 in every slice and can be sampled and its sampling inverted:
// Dupuy & Jakob 2018, "An Adaptive Parameterization for Efficient Material Acquisition and Rendering",
// §5: the marginal density of y is piecewise linear between rows (the rows' integrals), then x given y
// is piecewise linear between columns; each piece is inverted with the quadratic formula
//   ∫0^t ((1-s) a + s b) ds = a t + (b - a) t²/2 = u   =>   t = (a - sqrt(a² + 2 u (b - a))) / (a - b).
// Sampling (u -> p) and inversion (p -> u) are exact inverses of each other, and both give the density
// at p, which is the bilinear interpolant. This is the layout of the RGL `.bsdf` tables (bsdf/measured.h).
//
// The data are slices of ny rows of nx values (x fastest); the slice of parameter nodes (i0, i1, i2) is
// at index ((i0 n1) + i1) n2 + i2 (the last parameter fastest). Queries allocate nothing.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

class PiecewiseBilinear2D {
public:
    static constexpr int kMaxParams = 3;
    struct Sample {
        Point2f p;
        float pdf = 0; // density on [0, 1]^2 (the interpolant itself when not normalized)
    };

    PiecewiseBilinear2D() = default;
    // `params[k]`: the increasing node values of parameter k (at most kMaxParams parameters). `data`:
    // (product of the parameters' sizes) x ny x nx values, finite and non-negative when `normalized`.
    // nx, ny >= 2. With `normalized`, each slice is scaled to integrate to 1 (a slice that is 0
    // everywhere becomes uniform) and sample()/invert() may be used. Throws illum::Error on bad sizes.
    PiecewiseBilinear2D(std::vector<float> data, int nx, int ny, std::vector<std::vector<float>> params,
                        bool normalized);

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int param_count() const { return int(params_.size()); }

    // The interpolant at p in [0, 1]^2 (clamped), parameters clamped to their ranges.
    float evaluate(Point2f p, const float* param = nullptr) const;
    // A point distributed by the density, from u uniform in [0, 1)^2 (normalized only).
    Sample sample(Point2f u, const float* param = nullptr) const;
    // The u that sample() maps to p, and the density at p (normalized only).
    Sample invert(Point2f p, const float* param = nullptr) const;

private:
    // The slices surrounding a parameter point and their blending weights.
    struct Blend {
        std::array<std::uint32_t, 1 << kMaxParams> slice{};
        std::array<float, 1 << kMaxParams> weight{};
        int count = 0;
    };
    Blend blend(const float* param) const;
    // Σ weight · table[slice · stride + index].
    static float lookup(const std::vector<float>& table, std::size_t stride, std::size_t index,
                        const Blend& b) {
        float v = 0;
        for (int c = 0; c < b.count; ++c) v += b.weight[c] * table[b.slice[c] * stride + index];
        return v;
    }

    int nx_ = 0, ny_ = 0;
    bool normalized_ = false;
    float cells_ = 1; // (nx-1)(ny-1) when normalized: cell-unit densities times this are densities on [0,1]^2
    std::vector<std::vector<float>> params_;
    std::vector<float> data_;        // slices x ny x nx
    std::vector<float> conditional_; // slices x ny x nx: Σ over columns < x of the row's trapezoids
    std::vector<float> marginal_;    // slices x ny: Σ over rows < y of the trapezoids of row integrals
};

} // namespace illum
