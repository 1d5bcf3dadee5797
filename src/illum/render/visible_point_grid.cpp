#include "illum/render/visible_point_grid.h"

#include <algorithm>
#include <cmath>

#include "illum/math/rng.h"

namespace illum {

namespace {

constexpr int kMaxResolution = 1 << 20; // cells per axis, so a cell index fits in 60 bits

} // namespace

bool VisiblePointGrid::cell_of(Point3f x, std::uint64_t* cell) const {
    std::uint64_t index = 0;
    const float c[3] = {x.x - bounds_.lo.x, x.y - bounds_.lo.y, x.z - bounds_.lo.z};
    for (int a = 2; a >= 0; --a) {
        float f = c[a] * inv_cell_width_;
        if (!(f >= 0) || f >= float(res_[a])) return false;
        int i = std::min(int(f), res_[a] - 1);
        index = index * std::uint64_t(res_[a]) + std::uint64_t(i);
    }
    *cell = index;
    return true;
}

std::size_t VisiblePointGrid::bucket(std::uint64_t cell) const {
    return std::size_t(mix_bits(cell) & bucket_mask_);
}

void VisiblePointGrid::build(const std::vector<Point3f>& p, const std::vector<float>& r) {
    bounds_ = Bounds3f{};
    float r_max = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (!(r[i] > 0)) continue;
        bounds_.extend(Point3f{p[i].x - r[i], p[i].y - r[i], p[i].z - r[i]});
        bounds_.extend(Point3f{p[i].x + r[i], p[i].y + r[i], p[i].z + r[i]});
        r_max = std::max(r_max, r[i]);
        ++n;
    }
    entries_.clear();
    std::size_t buckets = 1;
    while (buckets < std::max<std::size_t>(n, 1) * 2) buckets *= 2;
    bucket_mask_ = buckets - 1;
    offsets_.assign(buckets + 1, 0);
    if (n == 0) {
        res_[0] = res_[1] = res_[2] = 0;
        return;
    }

    // Cells 2 r_max wide: a box of half-width r <= r_max spans at most two cells per axis.
    Vector3f diag = bounds_.diagonal();
    cell_width_ = 2 * r_max;
    float widest = std::max({diag.x, diag.y, diag.z});
    cell_width_ = std::max(cell_width_, widest / float(kMaxResolution - 1));
    inv_cell_width_ = 1 / cell_width_;
    const float d[3] = {diag.x, diag.y, diag.z};
    for (int a = 0; a < 3; ++a)
        res_[a] = std::clamp(int(std::ceil(d[a] * inv_cell_width_)), 1, kMaxResolution);

    // Every (point, cell) pair, in point order: counted per bucket in a first pass, placed in a second
    // (a counting sort without a copy of the pairs; stable: point order within a bucket).
    auto for_each_pair = [&](auto&& f) {
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (!(r[i] > 0)) continue;
            const float lo[3] = {p[i].x - r[i] - bounds_.lo.x, p[i].y - r[i] - bounds_.lo.y,
                                 p[i].z - r[i] - bounds_.lo.z};
            int c0[3], c1[3];
            for (int a = 0; a < 3; ++a) {
                c0[a] = std::clamp(int(lo[a] * inv_cell_width_), 0, res_[a] - 1);
                c1[a] = std::clamp(int((lo[a] + 2 * r[i]) * inv_cell_width_), 0, res_[a] - 1);
            }
            for (int z = c0[2]; z <= c1[2]; ++z)
                for (int y = c0[1]; y <= c1[1]; ++y)
                    for (int x = c0[0]; x <= c1[0]; ++x)
                        f(Entry{(std::uint64_t(z) * std::uint64_t(res_[1]) + std::uint64_t(y)) *
                                        std::uint64_t(res_[0]) +
                                    std::uint64_t(x),
                                std::uint32_t(i)});
        }
    };
    for_each_pair([&](const Entry& e) { ++offsets_[bucket(e.cell) + 1]; });
    for (std::size_t b = 0; b < buckets; ++b) offsets_[b + 1] += offsets_[b];
    entries_.resize(offsets_[buckets]);
    std::vector<std::uint32_t>& next = offsets_; // fill positions, restored below
    for_each_pair([&](const Entry& e) { entries_[next[bucket(e.cell)]++] = e; });
    // next[b] now holds the end of bucket b, which is the start of b + 1: shift back by one bucket.
    for (std::size_t b = buckets; b > 0; --b) offsets_[b] = offsets_[b - 1];
    offsets_[0] = 0;
}

} // namespace illum
