// PCG32 against the reference implementation's published output, stream jumps, and the hash helpers.
#include "illum/math/rng.h"

#include <gtest/gtest.h>

#include <bit>
#include <unordered_set>

#include "math/stat_util.h"

namespace illum {
namespace {

TEST(PCG32, MatchesReferenceOutput) {
    // pcg32-demo from the PCG distribution, seeded with pcg32_srandom(42, 54).
    PCG32 rng(42, 54);
    const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (uint32_t e : expected) EXPECT_EQ(rng.uniform_uint32(), e);
}

TEST(PCG32, AdvanceMatchesStepping) {
    PCG32 a(7, 3), b(7, 3);
    for (int i = 0; i < 1000; ++i) a.uniform_uint32();
    b.advance(1000);
    EXPECT_EQ(a, b);
    EXPECT_EQ(a.uniform_uint32(), b.uniform_uint32());
    b.advance(-1001);
    PCG32 c(7, 3);
    EXPECT_EQ(b, c);
}

TEST(PCG32, UniformFloatInUnitIntervalAndUniform) {
    EXPECT_LT(float(0xffffffffu >> 8) * 0x1p-24f, 1.0f); // the largest possible output
    PCG32 rng(1);
    const int n = 1 << 20, bins = 64;
    std::vector<double> observed(bins), expected(bins, double(n) / bins);
    test::MeanAccumulator mean;
    for (int i = 0; i < n; ++i) {
        float u = rng.uniform_float();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        observed[size_t(u * bins)] += 1;
        mean.add(u);
    }
    EXPECT_GT(test::chi2_test(observed, expected).p_value, 0.01);
    EXPECT_NEAR(mean.mean, 0.5, 5 * mean.std_error());
}

TEST(Hash, DistinctAndOrderSensitive) {
    EXPECT_NE(hash(1, 2), hash(2, 1));
    EXPECT_NE(hash(0), hash(0, 0));
    EXPECT_NE(hash(uint64_t(0)), hash(uint64_t(1)));
    EXPECT_EQ(hash(5, -3, 7u), hash(5, -3, 7u));
    // No collisions over a 256 x 256 pixel grid x 4 samples.
    std::unordered_set<uint64_t> seen;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x)
            for (int s = 0; s < 4; ++s) seen.insert(hash(uint64_t(0), x, y, s));
    EXPECT_EQ(seen.size(), size_t(256 * 256 * 4));
}

TEST(Hash, MixBitsAvalanche) {
    // Flipping one input bit flips each output bit with probability 1/2: 32 bits on average, variance 16
    // per trial for an ideal mixer. Checked over 64 bit positions x 2000 inputs.
    PCG32 rng(3);
    test::MeanAccumulator flips;
    for (int t = 0; t < 2000; ++t) {
        uint64_t x = (uint64_t(rng.uniform_uint32()) << 32) | rng.uniform_uint32();
        for (int b = 0; b < 64; ++b) flips.add(std::popcount(mix_bits(x) ^ mix_bits(x ^ (uint64_t(1) << b))));
    }
    EXPECT_NEAR(flips.mean, 32.0, 5 * std::sqrt(16.0 / double(flips.n)));
    // Sample variance of a near-normal variable: standard error σ² sqrt(2 / n).
    EXPECT_NEAR(flips.variance(), 16.0, 5 * 16.0 * std::sqrt(2.0 / double(flips.n)));
}

} // namespace
} // namespace illum
