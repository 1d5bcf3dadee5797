#include "illum/render/light_vertex_grid.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

constexpr int kMaxResolution = 1 << 20; // cells per axis, so a cell index fits in 60 bits

} // namespace

void LightVertexGrid::build(const std::vector<Point3f>& points, float r) {
    r_ = r;
    bounds_ = Bounds3f{};
    for (const Point3f& p : points) bounds_.extend(p);
    entries_.clear();
    std::size_t buckets = 1;
    while (buckets < std::max<std::size_t>(points.size(), 1) * 2) buckets *= 2;
    bucket_mask_ = buckets - 1;
    offsets_.assign(buckets + 1, 0);
    if (points.empty() || !(r > 0)) {
        entries_.clear();
        return;
    }
    Vector3f diag = bounds_.diagonal();
    float widest = std::max({diag.x, diag.y, diag.z});
    const float cell = std::max(2 * r, widest / float(kMaxResolution - 1));
    inv_cell_ = 1 / cell;
    const float d[3] = {diag.x, diag.y, diag.z};
    for (int a = 0; a < 3; ++a)
        res_[a] = std::clamp(int(std::floor(d[a] * inv_cell_)) + 1, 1, kMaxResolution);

    // Counting sort on the bucket, stable in the points' order.
    for (const Point3f& p : points) ++offsets_[bucket(cell_of(p)) + 1];
    for (std::size_t b = 0; b < buckets; ++b) offsets_[b + 1] += offsets_[b];
    entries_.resize(points.size());
    std::vector<std::uint32_t>& next = offsets_; // fill positions, restored below
    for (std::size_t i = 0; i < points.size(); ++i)
        entries_[next[bucket(cell_of(points[i]))]++] = Entry{points[i], std::uint32_t(i)};
    for (std::size_t b = buckets; b > 0; --b) offsets_[b] = offsets_[b - 1];
    offsets_[0] = 0;
}

void LightVertexGrid::number_by_cell(std::vector<std::uint32_t>* order) {
    order->resize(entries_.size());
    for (std::size_t e = 0; e < entries_.size(); ++e) {
        (*order)[e] = entries_[e].index;
        entries_[e].index = std::uint32_t(e);
    }
}

} // namespace illum
