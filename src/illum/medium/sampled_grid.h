// A voxel grid of samples, trilinearly interpolated, with pbrt-v4's SampledGrid conventions (pbrt-v4
// util/containers.h, SampledGrid::Lookup and MaxValue): nx x ny x nz samples over the unit cube, x
// fastest, sample (i, j, k) at the voxel centre ((i + 1/2) / nx, (j + 1/2) / ny, (k + 1/2) / nz); a
// lookup at p interpolates the eight samples around p · n - 1/2, and a sample index outside the grid reads
// as zero. So a value fades linearly to half of its boundary sample's at the cube's faces and to zero
// half a voxel beyond them (a 1x1x1 grid is a tent: its value at the centre, 1/2 on the faces, 1/8 at
// the corners). That is pbrt-v4's behaviour, kept so that scenes look the same.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "illum/math/bounds.h"
#include "illum/medium/majorant_grid.h"

namespace illum {

template <class T>
class SampledGrid {
public:
    SampledGrid() = default;
    // values.size() must be nx * ny * nz (the factories check it with a positioned error).
    SampledGrid(std::vector<T> values, int nx, int ny, int nz)
        : values_(std::move(values)), nx_(nx), ny_(ny), nz_(nz) {}

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int nz() const { return nz_; }
    std::size_t bytes() const { return values_.size() * sizeof(T); }
    const std::vector<T>& values() const { return values_; }

    // The sample at integer index (x, y, z); T{} outside the grid.
    T sample(int x, int y, int z) const {
        if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return T{};
        return values_[(std::size_t(z) * std::size_t(ny_) + std::size_t(y)) * std::size_t(nx_) +
                       std::size_t(x)];
    }

    // The interpolated value at p (unit-cube coordinates) of convert(sample): convert maps a sample to
    // something that scales and adds (float, SampledSpectrum, Color3).
    template <class F>
    auto lookup(Point3f p, F&& convert) const {
        using R = decltype(convert(T{}));
        // Samples influence p only within half a voxel of the cube; beyond that (and for NaN) the value is
        // zero, and the early exit keeps the integer conversion in range.
        if (!(p.x > -1 && p.x < 2 && p.y > -1 && p.y < 2 && p.z > -1 && p.z < 2)) return convert(T{});
        float sx = p.x * float(nx_) - 0.5f, sy = p.y * float(ny_) - 0.5f, sz = p.z * float(nz_) - 0.5f;
        float fx = std::floor(sx), fy = std::floor(sy), fz = std::floor(sz);
        int ix = int(fx), iy = int(fy), iz = int(fz);
        float dx = sx - fx, dy = sy - fy, dz = sz - fz;
        auto at = [&](int x, int y, int z) -> R { return convert(sample(x, y, z)); };
        auto mix = [](float t, const R& a, const R& b) -> R { return a * (1 - t) + b * t; };
        R x00 = mix(dx, at(ix, iy, iz), at(ix + 1, iy, iz));
        R x10 = mix(dx, at(ix, iy + 1, iz), at(ix + 1, iy + 1, iz));
        R x01 = mix(dx, at(ix, iy, iz + 1), at(ix + 1, iy, iz + 1));
        R x11 = mix(dx, at(ix, iy + 1, iz + 1), at(ix + 1, iy + 1, iz + 1));
        return mix(dz, mix(dy, x00, x10), mix(dy, x01, x11));
    }
    T lookup(Point3f p) const {
        return lookup(p, [](const T& v) { return v; });
    }

    // The largest bound(sample) over the samples that influence any point of b (unit-cube box): those
    // from floor(lo · n - 1/2) to floor(hi · n - 1/2) + 1, clamped to the grid (the samples outside read
    // as zero, which bounds nothing above a non-negative grid). The majorant of a trilinear grid.
    template <class F>
    float max_value(const Bounds3f& b, F&& bound) const {
        std::array<int, 3> lo{}, hi{};
        std::array<int, 3> n{nx_, ny_, nz_};
        for (int a = 0; a < 3; ++a) {
            auto ai = std::size_t(a);
            float l = b.lo[a] * float(n[ai]) - 0.5f, h = b.hi[a] * float(n[ai]) - 0.5f;
            lo[ai] = std::max(int(std::floor(l)), 0);
            hi[ai] = std::min(int(std::floor(h)) + 1, n[ai] - 1);
        }
        float m = 0;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) m = std::max(m, float(bound(sample(x, y, z))));
        return m;
    }

private:
    std::vector<T> values_;
    int nx_ = 0, ny_ = 0, nz_ = 0;
};

// A majorant grid of resolution res whose voxel (x, y, z) holds voxel_max(its unit-cube bounds).
template <class F>
MajorantGrid build_majorant_grid(std::array<int, 3> res, F&& voxel_max) {
    MajorantGrid g(res);
    for (int z = 0; z < res[2]; ++z)
        for (int y = 0; y < res[1]; ++y)
            for (int x = 0; x < res[0]; ++x) g.at(x, y, z) = voxel_max(g.voxel_bounds(x, y, z));
    return g;
}

} // namespace illum
