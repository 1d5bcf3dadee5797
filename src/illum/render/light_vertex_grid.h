// A hash grid over the light vertices of one VCM iteration for fixed-radius queries (PBR 3rd ed. §16.2.5's
// hashed uniform grid, turned around): each vertex is listed once, in the cell of width 2r that holds it,
// and a query at x visits the 2 × 2 × 2 cells that the box [x − r, x + r] overlaps. Compared with
// VisiblePointGrid (which lists a point in every cell its ball overlaps, up to 8, because there the query
// radius varies per point) this keeps one 16-byte entry per vertex, and the positions that the distance test
// reads sit in the entries themselves, in bucket order, instead of behind an index.
//
// Entries are placed by a counting sort on their bucket, stable in the vertices' order, so the order of
// the visits (and any sum over them) does not depend on the thread count. Rebuilt every iteration; the
// arrays keep their capacity.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "illum/math/bounds.h"
#include "illum/math/rng.h"

namespace illum {

class LightVertexGrid {
public:
    // Lists points[i] for every i, for queries of radius r.
    void build(const std::vector<Point3f>& points, float r);

    // Calls visit(std::uint32_t i) for every point within r of x (distance checked).
    template <class Visit>
    void for_within(Point3f x, Visit&& visit) const {
        if (entries_.empty()) return;
        int lo[3], hi[3];
        const float c[3] = {x.x - bounds_.lo.x, x.y - bounds_.lo.y, x.z - bounds_.lo.z};
        for (int a = 0; a < 3; ++a) {
            float f0 = (c[a] - r_) * inv_cell_, f1 = (c[a] + r_) * inv_cell_;
            if (!(f1 >= 0) || !(f0 < float(res_[a]))) return;
            lo[a] = f0 < 0 ? 0 : int(f0);
            hi[a] = f1 >= float(res_[a]) ? res_[a] - 1 : int(f1);
        }
        // The box spans at most 2 cells per axis (a cell is 2r wide; 3 allowed for rounding). The cells'
        // buckets and then their first entries are prefetched before any is read, so that their cache
        // misses overlap instead of following each other; the visits keep their order.
        constexpr int kMaxCells = 27;
        std::uint64_t cells[kMaxCells];
        std::size_t buckets[kMaxCells];
        std::uint32_t first[kMaxCells], last[kMaxCells];
        int n = 0;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int xx = lo[0]; xx <= hi[0] && n < kMaxCells; ++xx) {
                    cells[n] = cell_index(xx, y, z);
                    buckets[n] = bucket(cells[n]);
                    __builtin_prefetch(&offsets_[buckets[n]]);
                    ++n;
                }
        for (int k = 0; k < n; ++k) {
            first[k] = offsets_[buckets[k]];
            last[k] = offsets_[buckets[k] + 1];
            if (first[k] < last[k]) __builtin_prefetch(&entries_[first[k]]);
        }
        const float r2 = r_ * r_;
        for (int k = 0; k < n; ++k)
            for (std::uint32_t e = first[k]; e < last[k]; ++e) {
                const Entry& en = entries_[e];
                Vector3f d = en.p - x;
                if (d.x * d.x + d.y * d.y + d.z * d.z > r2) continue;
                // Two cells may share a bucket: visit a point from its own cell only.
                if (cell_of(en.p) != cells[k]) continue;
                visit(en.index);
            }
    }

    // Renumbers the points in the order of the grid's entries, cell by cell: afterwards visit() receives
    // the new numbers, and (*order)[k] is the point that now has number k. A caller that arranges its
    // per-point data by `order` reads it in sequence within a cell instead of at random.
    void number_by_cell(std::vector<std::uint32_t>* order);

    std::size_t size() const { return entries_.size(); }
    // Bytes held by the grid's arrays (capacity).
    std::size_t memory_bytes() const {
        return offsets_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(Entry);
    }

private:
    struct Entry {
        Point3f p;
        std::uint32_t index;
    };
    std::uint64_t cell_index(int x, int y, int z) const {
        return (std::uint64_t(z) * std::uint64_t(res_[1]) + std::uint64_t(y)) * std::uint64_t(res_[0]) +
               std::uint64_t(x);
    }
    std::uint64_t cell_of(Point3f p) const {
        const float c[3] = {p.x - bounds_.lo.x, p.y - bounds_.lo.y, p.z - bounds_.lo.z};
        int i[3];
        for (int a = 0; a < 3; ++a) i[a] = std::clamp(int(c[a] * inv_cell_), 0, res_[a] - 1);
        return cell_index(i[0], i[1], i[2]);
    }
    std::size_t bucket(std::uint64_t cell) const { return std::size_t(mix_bits(cell) & bucket_mask_); }

    Bounds3f bounds_;
    float r_ = 0, inv_cell_ = 0;
    int res_[3] = {0, 0, 0};
    std::uint64_t bucket_mask_ = 0;
    std::vector<std::uint32_t> offsets_;
    std::vector<Entry> entries_;
};

} // namespace illum
