// Progressive multi-jittered (0,2) sequences and a blue-noise tile, the tables of the pmj02bn sampler
// (sampler.h), generated here instead of loaded from pbrt-v4's data files.
//
// pmj02: P. Christensen, A. Kensler, C. Kilpatrick, "Progressive Multi-Jittered Sample Sequences" (EGSR
// 2018). Starting from one random point, the sequence doubles: for n = 4^k points, each of the n cells of
// side 1/sqrt(n) holds one point, and the next n points go one per cell into the sub-quadrant diagonally
// opposite the old point's; then the next 2n go into the two remaining sub-quadrants of every cell (which of
// the two first chosen at random). Within its sub-quadrant each new point takes a random position among
// those that leave every elementary interval of area 1/N (N the count after the step, a power of two)
// with one point, so every prefix of 2^m points is a (0, m, 2)-net. The valid positions are found as in M.
// Pharr, "Efficient Generation of Points that Satisfy Two-Dimensional Elementary Intervals" (JCGT 8(1),
// 2019): the admissible x strata (width 1/N) and y strata are found independently by descending the
// elementary-interval grids from the sub-quadrant's square, and any pair of them is admissible. With
// `candidates` > 1 each point is the best of that many admissible candidates by distance to its nearest
// neighbour (the "bn" variant: best-candidate blue noise, which keeps the (0,2) property).
//
// Best candidates were measured to widen the mean nearest-neighbour distance of 1024 points by only 2-5%
// (the net constraints leave few admissible positions), so the sampler's tables use one candidate.
//
// The blue-noise tile: R. Ulichney, "The void-and-cluster method for dither array generation" (SPIE 1993).
// A toroidal tile of kBlueNoiseSize^2 values in [0, 1), each value a rank: pixels are switched on one at a
// time, always where a Gaussian-filtered (σ = 1.5 pixels, truncated at 6) energy of those already on is
// lowest, after an initial 10% pattern has been relaxed by moving its tightest cluster into its largest
// void.
#pragma once

#include <cstdint>
#include <vector>

namespace illum::pmj02 {

// Points as 32-bit fixed-point fractions (value = x 2^-32).
struct FixedPoint2 {
    uint32_t x, y;
};

// The first n points (n a power of two) of a pmj02 sequence chosen by seed.
std::vector<FixedPoint2> generate(int n, uint64_t seed, int candidates = 1);

inline constexpr int kBlueNoiseSize = 64;
// kBlueNoiseSize^2 values, row-major; value (rank + 0.5) / size^2.
std::vector<float> blue_noise_tile(uint64_t seed);

} // namespace illum::pmj02
