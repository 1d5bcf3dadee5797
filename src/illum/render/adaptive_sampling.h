// Adaptive sampling: a render's samples spread over the pixels in rounds, more where the estimate of a pixel
// and its neighbours is noisier.
//
// With s_p² the variance of one sample of pixel p, its mean over n_p samples has variance s_p² / n_p, and
// for a given number of samples in all the image's mean squared error Σ s_p² / n_p is least when n_p ∝ s_p
// (a Lagrange multiplier: -(s_p / n_p)², the change of a pixel's error per added sample, is then the same
// for every pixel). So each round aims every pixel at
//     t_p = max(floor, s̃_p / λ),
// λ being the level at which these targets use up the budget (spp × pixels, or what the time left allows
// at the rate so far), and doubles the samples of the pixels whose target is above √2 times what they
// have (the pixels furthest below their targets first when the budget does not reach them all).
//
// The error estimate. A pixel's samples come from the sampler's low-discrepancy sequence, whose error falls
// faster than the samples' variance says (the pixel's area, at an edge of a light say, is stratified), so
// the variance of the samples would send far too many samples to such pixels. Each pixel's count is a power
// of two, and its first and second halves are each a stratified set of the sequence; with A and B their
// means (filter-weighted, per channel), (A - B)² / 4 estimates the squared error of the pixel's mean, and
//     s_p² = n_p · mean over the channels of (A - B)² / 4
// is the variance one independent sample would need to give that error. s̃_p² is s_p² averaged over the 5 × 5
// pixels around p, so that a pixel whose halves happen to agree (or that has not yet seen a rare bright
// path its neighbours have) is not stopped alone.
//
// The threshold: a pixel stops growing when its error level
//     e_p = s̃_p / (n_p · m̄) ≤ λ / m̄
// (m̄: the image's mean over the pixels and channels; s̃_p / n_p is how much, as a standard deviation, one more
// sample would lower the pixel's squared error). With a threshold T > 0, λ is at least T · m̄, so once every
// pixel has e_p ≤ T the render ends, before its budget if that is not spent by then; T = 0 lets the budget
// decide.
//
// Without a threshold the floor keeps every pixel at no less than a quarter of the mean number of samples
// (rounded down to a power of two): a pixel whose samples say little (a dark corner, a rare caustic) still
// takes samples. With one it is min_spp. The first rounds give every pixel min_spp / 2 and then min_spp.
//
// The plan depends only on the film's sums, which do not depend on the thread count: neither does the
// image. (Of the same family: Cycles' adaptive sampling, which compares the pixel with a second buffer of
// half its samples; Dammertz et al. 2010, "A hierarchical automatic stopping condition for Monte Carlo global
// illumination", whose error is |I - A| weighed by the square root of the brightness. This one aims at the
// mean squared error, which the renders are compared by.)
#pragma once

#include <cstdint>
#include <vector>

#include "illum/camera/film.h"

namespace illum {

struct AdaptiveSettings {
    bool enabled = false;
    double threshold = 0; // T above; 0: the budget decides
    int min_spp = 16;     // every pixel's samples after the first two rounds: a power of two, at least 2
};

class AdaptiveSchedule {
public:
    AdaptiveSchedule(const PixelBounds& bounds, const AdaptiveSettings& settings);

    // Plans the next round for a render of `budget` samples in all (the target of every round, not of this
    // one). Returns the samples the round adds: 0 when no pixel is to grow (below the threshold, or the
    // budget is spent), and then the round is not counted and may be planned again with another budget.
    // The film must hold exactly the samples of the rounds before.
    std::uint64_t plan(const Film& film, std::uint64_t budget);
    // The round's samples of pixel (x, y) (full-image raster, inside the bounds): [from, to).
    int from(int x, int y) const { return int(taken_[index(x, y)]); }
    int to(int x, int y) const { return int(target_[index(x, y)]); }
    // After the round: its samples are taken.
    void commit() { taken_ = target_; }
    // The round's work split for the threads: runs of pixels along each row, [x0, x1) in row y, each holding
    // about `max_samples` of the round's samples (a pixel with more is a run of its own), so that the
    // threads finish the round together although a few pixels take most of its samples. Pixels without
    // samples in the round are left out at the runs' ends.
    struct Run {
        int y, x0, x1;
    };
    std::vector<Run> round_runs(std::uint64_t max_samples) const;

    std::uint64_t taken() const;
    std::size_t pixels() const { return taken_.size(); }
    // The rounds planned with samples to add.
    int rounds() const { return rounds_; }
    // λ / m̄ of the last round that planned by the estimates: its error level (0 before).
    double level() const { return level_; }
    std::uint32_t min_taken() const;
    std::uint32_t max_taken() const;

private:
    std::size_t index(int x, int y) const {
        return std::size_t(y - bounds_.y0) * std::size_t(bounds_.width()) + std::size_t(x - bounds_.x0);
    }
    std::uint64_t plan_round(const Film& film, std::uint64_t budget);
    // s̃ of every pixel (above).
    std::vector<double> smoothed_deviation(const Film& film) const;
    // Every pixel with grow[i] doubles; its sums so far become its first half.
    std::uint64_t double_pixels(const Film& film, const std::vector<char>& grow);

    PixelBounds bounds_;
    AdaptiveSettings settings_;
    std::vector<std::uint32_t> taken_, target_;
    std::vector<double> half_; // per pixel: the film's four sums when it had half its samples
    int rounds_ = 0;
    double level_ = 0;
};

} // namespace illum
