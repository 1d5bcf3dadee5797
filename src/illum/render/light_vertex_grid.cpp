#include "illum/render/light_vertex_grid.h"

#include <algorithm>
#include <cmath>

#include "illum/math/rng.h"

namespace illum {

namespace {

constexpr int kMaxResolution = 1 << 20; // cells per axis, so a cell index fits in 60 bits

} // namespace

std::uint64_t LightVertexGrid::cell_of(Point3f p) const {
    const float c[3] = {p.x - bounds_.lo.x, p.y - bounds_.lo.y, p.z - bounds_.lo.z};
    int i[3];
    for (int a = 0; a < 3; ++a) i[a] = std::clamp(int(c[a] * inv_cell_), 0, res_[a] - 1);
    return cell_index(i[0], i[1], i[2]);
}

std::size_t LightVertexGrid::bucket(std::uint64_t cell) const {
    return std::size_t(mix_bits(cell) & bucket_mask_);
}

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

} // namespace illum
