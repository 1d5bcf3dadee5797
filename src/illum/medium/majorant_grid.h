// A coarse grid of upper bounds on a medium's density (the majorant grid), and the walk of a ray through
// its voxels (a 3D DDA: Amanatides & Woo 1987, "A Fast Voxel Traversal Algorithm for Ray Tracing"), giving
// the ray's majorant as piecewise constant in t. Delta and ratio tracking sample against these segments
// (Pharr, Jakob & Humphreys, PBR 4th ed., §11.4), so a sparse or peaked density costs only where it is.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "illum/math/bounds.h"
#include "illum/radiometry/sampled_spectrum.h"

namespace illum {

// The part of a ray in which the majorant σ_maj is constant: t in [t0, t1).
struct MajorantSegment {
    float t0 = 0, t1 = 0;
    SampledSpectrum sigma_maj;
};

// res[0] x res[1] x res[2] voxels over the unit cube (the medium's bounds mapped to [0, 1]^3), x fastest.
class MajorantGrid {
public:
    MajorantGrid() = default;
    explicit MajorantGrid(std::array<int, 3> res)
        : res_(res), values_(std::size_t(res[0]) * std::size_t(res[1]) * std::size_t(res[2]), 0.0f) {}

    const std::array<int, 3>& res() const { return res_; }
    float at(int x, int y, int z) const { return values_[index(x, y, z)]; }
    float& at(int x, int y, int z) { return values_[index(x, y, z)]; }
    // The unit-cube box that voxel (x, y, z) covers.
    Bounds3f voxel_bounds(int x, int y, int z) const {
        Bounds3f b;
        b.lo = {float(x) / float(res_[0]), float(y) / float(res_[1]), float(z) / float(res_[2])};
        b.hi = {float(x + 1) / float(res_[0]), float(y + 1) / float(res_[1]), float(z + 1) / float(res_[2])};
        return b;
    }
    std::size_t bytes() const { return values_.size() * sizeof(float); }

private:
    std::size_t index(int x, int y, int z) const {
        return (std::size_t(z) * std::size_t(res_[1]) + std::size_t(y)) * std::size_t(res_[0]) +
               std::size_t(x);
    }
    std::array<int, 3> res_{0, 0, 0};
    std::vector<float> values_;
};

// The majorant segments along a ray, in order: one for a homogeneous medium, a voxel walk for a grid. A
// value type (no allocation); `next()` returns nothing once the ray has left the medium or reached tmax.
class MajorantIterator {
public:
    MajorantIterator() = default; // no segments: the ray misses the medium
    // One segment [t0, t1) with majorant sigma_maj.
    static MajorantIterator single(float t0, float t1, SampledSpectrum sigma_maj);
    // The voxels of `grid` along the ray o + t d given in the grid's unit-cube space (d not normalised: t
    // is the caller's parameter), from t0 to t1 (already clipped to the cube); each voxel's majorant is
    // sigma_t times the grid's value.
    static MajorantIterator dda(const MajorantGrid* grid, Point3f o, Vector3f d, float t0, float t1,
                                SampledSpectrum sigma_t);

    std::optional<MajorantSegment> next();

private:
    const MajorantGrid* grid_ = nullptr;
    SampledSpectrum sigma_; // single: the majorant; dda: σ_t to scale the grid's values by
    float t0_ = 0, t1_ = 0;
    bool done_ = true;
    // DDA state: the current voxel, the t at which the ray crosses into the next voxel along each axis,
    // the t step between crossings, the step direction and the voxel index at which the walk leaves.
    std::array<int, 3> voxel_{}, step_{}, out_{};
    std::array<float, 3> next_crossing_{}, delta_t_{};
};

} // namespace illum
