// A uniform grid over the visible points of one SPPM iteration, hashed into buckets (PBR 3rd ed. §16.2.5;
// pbrt-v4's SPPM grid): each visible point of radius r is listed in every cell its box [p - r, p + r]
// overlaps, so a photon arriving at x finds every visible point within its radius among the entries of
// x's cell. The cell width is twice the largest radius, so a point's box overlaps at most 2 × 2 × 2 cells
// (pbrt-v4's cells are one radius wide, up to 27 per point).
//
// Stored compactly (CSR): one offset per bucket and one entry per (point, cell); each entry keeps its
// cell's index, so two cells that hash to one bucket are told apart and a point is never found twice for
// one photon. Rebuilt every iteration as the radii shrink; the arrays keep their capacity, so a rebuild
// allocates nothing after the first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "illum/math/bounds.h"

namespace illum {

class VisiblePointGrid {
public:
    // Lists point i (position p[i], radius r[i]) when r[i] > 0; a point with r[i] <= 0 is absent.
    void build(const std::vector<Point3f>& p, const std::vector<float>& r);

    // Calls visit(std::uint32_t point) for each point listed in the cell of x (a superset of the points
    // within their radius of x; the caller checks the distance).
    template <class Visit>
    void for_candidates(Point3f x, Visit&& visit) const {
        std::uint64_t cell;
        if (!cell_of(x, &cell)) return;
        std::size_t b = bucket(cell);
        for (std::uint32_t e = offsets_[b]; e < offsets_[b + 1]; ++e)
            if (entries_[e].cell == cell) visit(entries_[e].point);
    }

    std::size_t entry_count() const { return entries_.size(); }
    std::size_t bucket_count() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
    // Bytes held by the grid's arrays (capacity).
    std::size_t memory_bytes() const {
        return offsets_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(Entry);
    }
    float cell_width() const { return cell_width_; }

private:
    struct Entry {
        std::uint64_t cell;
        std::uint32_t point;
    };
    // The cell of x as one index ((z · ny + y) · nx + x); false outside the grid.
    bool cell_of(Point3f x, std::uint64_t* cell) const;
    std::size_t bucket(std::uint64_t cell) const;

    Bounds3f bounds_;
    float cell_width_ = 0, inv_cell_width_ = 0;
    int res_[3] = {0, 0, 0};
    std::uint64_t bucket_mask_ = 0;
    std::vector<std::uint32_t> offsets_; // bucket b's entries are entries_[offsets_[b], offsets_[b + 1])
    std::vector<Entry> entries_;
};

} // namespace illum
