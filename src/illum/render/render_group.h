// The processes that render one image together (the ranks of an MPI run, apps/illum/mpi_render_group.*).
// Rank r of n renders pixel samples s ≡ r (mod n) of every pixel, with the same deterministic sampler
// state (seed, pixel, s) a single process would use, so the union over ranks is exactly the single-process
// set of samples; the render loops then sum their accumulators (film sums, weights, counters) over the
// group and rank 0 resolves and writes the image. A time budget is rank 0's clock: after every pass rank
// 0 says whether another pass follows, so every rank renders the same number of passes.
//
// The render module knows the group only through this interface: it needs no MPI.
#pragma once

#include <cstdint>
#include <span>

namespace illum {

class RenderGroup {
public:
    virtual ~RenderGroup() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // Sums `values` element-wise over the group. Afterwards rank 0 holds the sum; with `everywhere` every
    // rank holds it, with the same bits on every rank (reduced on rank 0, then broadcast).
    virtual void sum(std::span<double> values, bool everywhere) = 0;
    // Rank 0's value, on every rank.
    virtual bool broadcast(bool value) = 0;
    // Seconds spent in sum() and broadcast() (communication and waiting for the slowest rank).
    double communication_seconds = 0;
};

// One share of a group rendered alone: what rank `rank` of `size` would render, with sums that stay local
// (`illum render --share R/N`, to time the ranks of a large run one by one on one machine). Its image is
// the mean of its own samples only.
class SoloShare final : public RenderGroup {
public:
    SoloShare(int rank, int size) : rank_(rank), size_(size) {}
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    void sum(std::span<double>, bool) override {}
    bool broadcast(bool value) override { return value; }

private:
    int rank_, size_;
};

// The pixel-sample indices one rank renders: s = first + k·stride for k = 0, 1, ...
struct SampleShare {
    int first = 0;  // the rank
    int stride = 1; // the group's size
    // How many of the samples [0, spp) fall to this share.
    int count(int spp) const { return spp > first ? (spp - first + stride - 1) / stride : 0; }
    // The global sample index of this share's k-th sample (its k-th pass).
    int index(int k) const { return first + k * stride; }
};

inline SampleShare sample_share(const RenderGroup* group) {
    return group ? SampleShare{group->rank(), group->size()} : SampleShare{};
}

// Sums a counter over the group (exact below 2^53), on rank 0.
inline std::uint64_t sum_counter(RenderGroup* group, std::uint64_t value) {
    if (!group) return value;
    double v = double(value);
    group->sum(std::span<double>(&v, 1), false);
    return std::uint64_t(v);
}

} // namespace illum
