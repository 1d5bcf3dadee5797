#include "illum/render/pmj02.h"

#include <cmath>
#include <limits>

#include "illum/math/rng.h"
#include "illum/util/error.h"

namespace illum::pmj02 {

namespace {

// The elementary intervals of area 2^-m as occupancy grids: grid i (0..m) has 2^(m-i) columns and 2^i
// rows, so grid 0 is the finest x strata and grid m the finest y strata.
class Strata {
public:
    void subdivide(int m, const std::vector<FixedPoint2>& pts, int count) {
        m_ = m;
        occupied_.assign(size_t(m + 1) << m, 0);
        for (int k = 0; k < count; ++k) mark(pts[size_t(k)]);
    }

    void mark(FixedPoint2 p) {
        for (int i = 0; i <= m_; ++i) occupied_[index(i, column(p.x, m_ - i), column(p.y, i))] = 1;
    }

    // The finest x strata and y strata a new point in sub-quadrant (qx, qy) of a grid of 2^d x 2^d may
    // take (Pharr 2019). m = 2d: the square grid d holds the sub-quadrant; m = 2d - 1: the sub-quadrant is
    // half of a cell of grid d - 1 (2^d x 2^(d-1)) and of grid d (2^(d-1) x 2^d).
    void admissible(int d, uint32_t qx, uint32_t qy, std::vector<uint32_t>& xs,
                    std::vector<uint32_t>& ys) const {
        xs.clear(), ys.clear();
        if (m_ == 2 * d) {
            descend_x(d, qx, qy, xs);
            descend_y(d, qx, qy, ys);
        } else {
            descend_x(d - 1, qx, qy >> 1, xs);
            descend_y(d, qx >> 1, qy, ys);
        }
    }

private:
    static uint32_t column(uint32_t v, int bits) { return bits == 0 ? 0u : v >> (32 - bits); }
    size_t index(int i, uint32_t col, uint32_t row) const {
        return (size_t(i) << m_) + (size_t(row) << (m_ - i)) + col;
    }
    // Towards more columns: an empty interval's two halves in x (each half as tall again).
    void descend_x(int i, uint32_t col, uint32_t row, std::vector<uint32_t>& out) const {
        if (occupied_[index(i, col, row)]) return;
        if (i == 0) {
            out.push_back(col);
            return;
        }
        descend_x(i - 1, 2 * col, row >> 1, out);
        descend_x(i - 1, 2 * col + 1, row >> 1, out);
    }
    void descend_y(int i, uint32_t col, uint32_t row, std::vector<uint32_t>& out) const {
        if (occupied_[index(i, col, row)]) return;
        if (i == m_) {
            out.push_back(row);
            return;
        }
        descend_y(i + 1, col >> 1, 2 * row, out);
        descend_y(i + 1, col >> 1, 2 * row + 1, out);
    }

    int m_ = 0;
    std::vector<uint8_t> occupied_;
};

// Which point (index) lies in each cell of a 2^d x 2^d grid, for nearest-neighbour distances.
class NeighbourGrid {
public:
    void reset(int d, const std::vector<FixedPoint2>& pts, int count) {
        d_ = d;
        cells_.assign(size_t(1) << (2 * d), -1);
        for (int k = 0; k < count; ++k) add(pts[size_t(k)], k);
    }
    void add(FixedPoint2 p, int k) { cells_[cell(p.x, p.y)] = k; }
    // Squared toroidal distance to the nearest point within two cells, in units of the cell.
    double nearest(FixedPoint2 p, const std::vector<FixedPoint2>& pts) const {
        const int n = 1 << d_;
        const int cx = int(p.x >> (32 - d_)), cy = int(p.y >> (32 - d_));
        double best = std::numeric_limits<double>::infinity();
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                int k = cells_[size_t(((cy + dy) & (n - 1)) * n + ((cx + dx) & (n - 1)))];
                if (k < 0) continue;
                auto delta = [&](uint32_t a, uint32_t b) {
                    double t = double(int32_t(a - b)) * 0x1p-32 * n; // toroidal difference
                    return t * t;
                };
                best = std::min(best, delta(p.x, pts[size_t(k)].x) + delta(p.y, pts[size_t(k)].y));
            }
        return best;
    }

private:
    size_t cell(uint32_t x, uint32_t y) const {
        return size_t(y >> (32 - d_)) * (size_t(1) << d_) + size_t(x >> (32 - d_));
    }
    int d_ = 1;
    std::vector<int> cells_;
};

class Generator {
public:
    Generator(int n, uint64_t seed, int candidates)
        : pts_(size_t(n)), rng_(seed, mix_bits(seed + 1)), candidates_(candidates) {}

    // False when some point found no admissible position (never observed; the caller reseeds).
    bool run() {
        const int n = int(pts_.size());
        pts_[0] = {rng_.uniform_uint32(), rng_.uniform_uint32()};
        int count = 1, m = 0, d = 0; // count = 4^d = 2^m points so far
        while (count < n) {
            // Even step: count -> 2 count, sub-quadrants of a 2^(d+1) grid, the diagonal one.
            ++m, ++d;
            strata_.subdivide(m, pts_, count);
            neighbours_.reset(d, pts_, count);
            for (int k = 0; k < count && count + k < n; ++k) {
                uint32_t qx = pts_[size_t(k)].x >> (32 - d), qy = pts_[size_t(k)].y >> (32 - d);
                if (!place(count + k, d, qx ^ 1u, qy ^ 1u)) return false;
            }
            if (2 * count >= n) break;
            // Odd step: 2 count -> 4 count, the two remaining sub-quadrants of every cell, one in each half.
            ++m;
            strata_.subdivide(m, pts_, 2 * count);
            neighbours_.reset(d, pts_, 2 * count);
            std::vector<uint8_t> swap_x(static_cast<size_t>(count));
            for (int k = 0; k < count && 2 * count + k < n; ++k) {
                swap_x[size_t(k)] = uint8_t(rng_.uniform_uint32() & 1u);
                uint32_t qx = pts_[size_t(k)].x >> (32 - d), qy = pts_[size_t(k)].y >> (32 - d);
                if (!place(2 * count + k, d, swap_x[size_t(k)] ? qx ^ 1u : qx,
                           swap_x[size_t(k)] ? qy : qy ^ 1u))
                    return false;
            }
            for (int k = 0; k < count && 3 * count + k < n; ++k) {
                uint32_t qx = pts_[size_t(k)].x >> (32 - d), qy = pts_[size_t(k)].y >> (32 - d);
                if (!place(3 * count + k, d, swap_x[size_t(k)] ? qx : qx ^ 1u,
                           swap_x[size_t(k)] ? qy ^ 1u : qy))
                    return false;
            }
            count *= 4;
        }
        return true;
    }

    std::vector<FixedPoint2> take() { return std::move(pts_); }

private:
    // A uniformly random point of finest stratum s (of 2^m) in one coordinate.
    uint32_t jitter(uint32_t s, int m) {
        uint32_t low = m == 32 ? 0u : rng_.uniform_uint32() >> m;
        return m == 0 ? low : (s << (32 - m)) | low;
    }

    bool place(int k, int d, uint32_t qx, uint32_t qy) {
        strata_.admissible(d, qx, qy, xs_, ys_);
        if (xs_.empty() || ys_.empty()) return false;
        const int m = m_of(k);
        FixedPoint2 best{};
        double best_distance = -1;
        for (int c = 0; c < candidates_; ++c) {
            uint32_t sx = xs_[rng_.uniform_uint32() % xs_.size()],
                     sy = ys_[rng_.uniform_uint32() % ys_.size()];
            FixedPoint2 p{jitter(sx, m), jitter(sy, m)};
            double dist = candidates_ > 1 ? neighbours_.nearest(p, pts_) : 0;
            if (dist > best_distance) best = p, best_distance = dist;
        }
        pts_[size_t(k)] = best;
        strata_.mark(best);
        neighbours_.add(best, k);
        return true;
    }

    // log2 of the count at the end of the step that places point k.
    static int m_of(int k) {
        int m = 0;
        while ((1 << m) <= k) ++m;
        return m;
    }

    std::vector<FixedPoint2> pts_;
    PCG32 rng_;
    int candidates_;
    Strata strata_;
    NeighbourGrid neighbours_;
    std::vector<uint32_t> xs_, ys_;
};

} // namespace

std::vector<FixedPoint2> generate(int n, uint64_t seed, int candidates) {
    if (n < 1 || (n & (n - 1)) != 0) throw Error("pmj02: the point count must be a power of two");
    for (uint64_t attempt = 0;; ++attempt) {
        Generator g(n, hash(seed, attempt), candidates);
        if (g.run()) return g.take();
    }
}

std::vector<float> blue_noise_tile(uint64_t seed) {
    constexpr int S = kBlueNoiseSize, N = S * S, R = 6; // the kernel is below 4e-4 of its peak beyond R
    // Gaussian kernel, σ = 1.5 pixels, truncated to |dx|, |dy| <= R, applied toroidally.
    double kernel[2 * R + 1][2 * R + 1];
    for (int dy = -R; dy <= R; ++dy)
        for (int dx = -R; dx <= R; ++dx)
            kernel[dy + R][dx + R] = std::exp(-(dx * dx + dy * dy) / (2 * 1.5 * 1.5));
    std::vector<double> energy(size_t(N), 0.0);
    std::vector<uint8_t> on(size_t(N), 0);
    auto toggle = [&](std::vector<uint8_t>& pattern, std::vector<double>& e, int p, bool value) {
        pattern[size_t(p)] = value;
        const double sign = value ? 1 : -1;
        const int px = p % S, py = p / S;
        for (int dy = -R; dy <= R; ++dy)
            for (int dx = -R; dx <= R; ++dx)
                e[size_t(((py + dy + S) % S) * S + (px + dx + S) % S)] += sign * kernel[dy + R][dx + R];
    };
    // Tightest cluster: the "on" pixel of highest energy; largest void: the "off" pixel of lowest.
    auto extreme = [&](const std::vector<uint8_t>& pattern, const std::vector<double>& e, bool cluster) {
        int best = -1;
        for (int p = 0; p < N; ++p) {
            if (bool(pattern[size_t(p)]) != cluster) continue;
            if (best < 0 || (cluster ? e[size_t(p)] > e[size_t(best)] : e[size_t(p)] < e[size_t(best)]))
                best = p;
        }
        return best;
    };

    PCG32 rng(seed, 0x5eed);
    const int initial = N / 10;
    for (int placed = 0; placed < initial;) {
        int p = int(rng.uniform_uint32() % uint32_t(N));
        if (!on[size_t(p)]) toggle(on, energy, p, true), ++placed;
    }
    // Relax the initial pattern: move the tightest cluster into the largest void until that is a no-op (or,
    // should two pixels trade places forever, for at most as many moves as there are pixels on).
    for (int iter = 0; iter < initial; ++iter) {
        int c = extreme(on, energy, true);
        toggle(on, energy, c, false);
        int v = extreme(on, energy, false);
        toggle(on, energy, v, true);
        if (v == c) break;
    }
    std::vector<int> rank(size_t(N), -1);
    {
        // Phase 1: rank the initial pixels by removing tightest clusters.
        std::vector<uint8_t> pattern = on;
        std::vector<double> e = energy;
        for (int r = initial - 1; r >= 0; --r) {
            int c = extreme(pattern, e, true);
            rank[size_t(c)] = r;
            toggle(pattern, e, c, false);
        }
    }
    // Phases 2 and 3: fill the largest void until every pixel is on (for the second half, the largest void
    // of the "on" pixels is the tightest cluster of the "off" ones: the same choice).
    for (int r = initial; r < N; ++r) {
        int v = extreme(on, energy, false);
        rank[size_t(v)] = r;
        toggle(on, energy, v, true);
    }
    std::vector<float> out(static_cast<size_t>(N));
    for (int p = 0; p < N; ++p) out[size_t(p)] = (float(rank[size_t(p)]) + 0.5f) / float(N);
    return out;
}

} // namespace illum::pmj02
