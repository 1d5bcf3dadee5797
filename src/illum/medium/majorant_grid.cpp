#include "illum/medium/majorant_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace illum {

MajorantIterator MajorantIterator::single(float t0, float t1, SampledSpectrum sigma_maj) {
    MajorantIterator it;
    it.sigma_ = sigma_maj;
    it.t0_ = t0;
    it.t1_ = t1;
    it.done_ = !(t0 < t1);
    return it;
}

MajorantIterator MajorantIterator::dda(const MajorantGrid* grid, Point3f o, Vector3f d, float t0, float t1,
                                       SampledSpectrum sigma_t) {
    MajorantIterator it;
    it.grid_ = grid;
    it.sigma_ = sigma_t;
    it.t0_ = t0;
    it.t1_ = t1;
    it.done_ = !(t0 < t1);
    if (it.done_) return it;
    Point3f p = o + d * t0; // where the walk starts, inside (or on) the unit cube
    for (int a = 0; a < 3; ++a) {
        int n = grid->res()[std::size_t(a)];
        auto ai = std::size_t(a);
        it.voxel_[ai] = std::clamp(int(p[a] * float(n)), 0, n - 1);
        it.delta_t_[ai] = 1 / (std::abs(d[a]) * float(n)); // inf when the ray is parallel to the axis
        if (d[a] >= 0) {
            // Crossing into voxel v + 1 happens at the plane (v + 1) / n.
            float next = float(it.voxel_[ai] + 1) / float(n);
            it.next_crossing_[ai] =
                d[a] > 0 ? t0 + (next - p[a]) / d[a] : std::numeric_limits<float>::infinity();
            it.step_[ai] = 1;
            it.out_[ai] = n;
        } else {
            float next = float(it.voxel_[ai]) / float(n);
            it.next_crossing_[ai] = t0 + (next - p[a]) / d[a];
            it.step_[ai] = -1;
            it.out_[ai] = -1;
        }
    }
    return it;
}

std::optional<MajorantSegment> MajorantIterator::next() {
    if (done_) return std::nullopt;
    if (!grid_) {
        done_ = true;
        return MajorantSegment{t0_, t1_, sigma_};
    }
    // The axis whose crossing comes first ends this voxel.
    int axis = 0;
    if (next_crossing_[1] < next_crossing_[std::size_t(axis)]) axis = 1;
    if (next_crossing_[2] < next_crossing_[std::size_t(axis)]) axis = 2;
    auto a = std::size_t(axis);
    float voxel_exit = std::min(t1_, next_crossing_[a]);
    MajorantSegment seg{t0_, voxel_exit, sigma_ * grid_->at(voxel_[0], voxel_[1], voxel_[2])};
    t0_ = voxel_exit;
    if (next_crossing_[a] > t1_) done_ = true;
    voxel_[a] += step_[a];
    if (voxel_[a] == out_[a]) done_ = true;
    next_crossing_[a] += delta_t_[a];
    return seg;
}

} // namespace illum
