// The building blocks of the low-discrepancy samplers: primes, radical inverses and their inverse,
// modular inverses, hashed permutations, the digit scrambles, Morton codes; the pmj02 sequences (every
// power-of-two prefix a (0, m, 2)-net) and the blue-noise tile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "illum/render/low_discrepancy.h"
#include "illum/render/pmj02.h"

namespace illum {
namespace {

using namespace low_discrepancy;

TEST(LowDiscrepancy, Primes) {
    const auto& p = primes();
    const uint32_t first[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29};
    for (int i = 0; i < 10; ++i) EXPECT_EQ(p[size_t(i)], first[i]);
    EXPECT_EQ(p[99], 541u);
    EXPECT_EQ(p[999], 7919u);
    for (size_t i = 0; i < p.size(); ++i)
        for (uint32_t d = 2; d * d <= p[i]; ++d) ASSERT_NE(p[i] % d, 0u) << p[i];
}

TEST(LowDiscrepancy, RadicalInverseAndItsInverse) {
    EXPECT_EQ(radical_inverse(0, 0), 0.0f);
    EXPECT_EQ(radical_inverse(0, 1), 0.5f);
    EXPECT_EQ(radical_inverse(0, 3), 0.75f);
    EXPECT_FLOAT_EQ(radical_inverse(1, 1), 1.0f / 3);
    EXPECT_FLOAT_EQ(radical_inverse(1, 4), 1.0f / 3 + 1.0f / 9);     // 11_3
    EXPECT_FLOAT_EQ(radical_inverse(4, 12), 1.0f / 11 + 1.0f / 121); // 11_11
    EXPECT_LT(radical_inverse(0, ~uint64_t(0)), 1.0f);
    // inverse_radical_inverse(b^n Φ_b(a), b, n) = a for a < b^n.
    for (int base : {2, 3, 5}) {
        const int n = 5;
        uint64_t bn = 1;
        for (int i = 0; i < n; ++i) bn *= uint64_t(base);
        for (uint64_t a = 0; a < bn; a += 7) {
            int idx = base == 2 ? 0 : base == 3 ? 1 : 2;
            uint64_t inv = uint64_t(std::llround(double(radical_inverse(idx, a)) * double(bn)));
            EXPECT_EQ(inverse_radical_inverse(inv, base, n), a);
        }
    }
}

TEST(LowDiscrepancy, MultiplicativeInverse) {
    for (int64_t n : {4, 9, 27, 128, 243, 7919})
        for (int64_t a : {1, 2, 3, 5, 7, 81, 256, 1000})
            if (std::gcd(a, n) == 1) {
                int64_t x = multiplicative_inverse(a, n);
                EXPECT_GE(x, 0);
                EXPECT_LT(x, n);
                EXPECT_EQ((a % n) * x % n, 1 % n) << a << " mod " << n;
            }
}

TEST(LowDiscrepancy, PermutationElementIsAPermutation) {
    for (uint32_t n : {1u, 2u, 3u, 7u, 16u, 100u, 1000u, 4097u})
        for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
            std::vector<int> seen(n, 0);
            for (uint32_t i = 0; i < n; ++i) {
                uint32_t j = permutation_element(i, n, seed);
                ASSERT_LT(j, n);
                ++seen[j];
            }
            for (int c : seen) ASSERT_EQ(c, 1);
        }
    // Different seeds, different permutations; and not the identity.
    int same = 0, fixed = 0;
    for (uint32_t i = 0; i < 1000; ++i) {
        same += permutation_element(i, 1000, 1) == permutation_element(i, 1000, 2);
        fixed += permutation_element(i, 1000, 1) == i;
    }
    EXPECT_LT(same, 20);
    EXPECT_LT(fixed, 20);
}

TEST(LowDiscrepancy, DigitScramblesAreBijectionsOnStrata) {
    // permutedigits: each digit permuted by its own permutation, so the b^2 values Φ(a) for a < b^2 stay
    // one per stratum of width b^-2, and every table is a permutation.
    auto tables = make_digit_permutations(42);
    ASSERT_EQ(tables.size(), size_t(kPrimeCount));
    for (int k : {0, 1, 2, 10, 999}) {
        const DigitPermutations& t = tables[size_t(k)];
        EXPECT_EQ(t.base, int(primes()[size_t(k)]));
        EXPECT_GE(std::pow(double(t.base), t.n_digits), double(1 << 24));
        for (int d = 0; d < t.n_digits; ++d) {
            std::vector<uint16_t> p(t.perm.begin() + d * t.base, t.perm.begin() + (d + 1) * t.base);
            std::sort(p.begin(), p.end());
            for (int j = 0; j < t.base; ++j) ASSERT_EQ(p[size_t(j)], j);
        }
    }
    for (int k : {0, 1, 2, 3}) {
        const int b = int(primes()[size_t(k)]), n = b * b;
        std::vector<int> a(size_t(n), 0), c(size_t(n), 0);
        for (int i = 0; i < n; ++i) {
            ++a[size_t(scrambled_radical_inverse(tables[size_t(k)], uint64_t(i)) * n)];
            ++c[size_t(owen_scrambled_radical_inverse(k, uint64_t(i), 77) * n)];
        }
        for (int i = 0; i < n; ++i) {
            EXPECT_EQ(a[size_t(i)], 1);
            EXPECT_EQ(c[size_t(i)], 1);
        }
    }
    // Base 2: the first 2^k Sobol (van der Corput) points stay stratified under every scramble.
    for (Randomization r :
         {Randomization::none, Randomization::permute_digits, Randomization::fast_owen, Randomization::owen})
        for (int k : {1, 4, 8}) {
            std::vector<int> count(size_t(1) << k, 0);
            for (uint32_t i = 0; i < (1u << k); ++i)
                ++count[scramble_base2(sampling_detail::sobol_dim0(i), 12345u, r) >> (32 - k)];
            for (int c : count) EXPECT_EQ(c, 1) << randomization_name(r);
        }
    // The exact Owen scramble flips the leading bit with the seed's hash and depends only on the bits
    // above: x and x' sharing their top 8 bits share the top 9 bits of the result.
    for (uint32_t x : {0x12345678u, 0xfedcba98u}) {
        uint32_t y = x ^ 0x007fffffu;
        EXPECT_EQ(owen_base2(x, 5) >> 23, owen_base2(y, 5) >> 23);
        EXPECT_NE(owen_base2(x, 5), owen_base2(y, 5));
    }
}

TEST(LowDiscrepancy, MortonCode) {
    EXPECT_EQ(morton_2d(0, 0), 0u);
    EXPECT_EQ(morton_2d(1, 0), 1u);
    EXPECT_EQ(morton_2d(0, 1), 2u);
    EXPECT_EQ(morton_2d(3, 5), 0b100111u); // x = 011, y = 101 -> y2 x2 y1 x1 y0 x0 = 1 0 0 1 1 1
    EXPECT_EQ(morton_2d(0xffffffffu, 0), 0x5555555555555555ULL);
    EXPECT_EQ(morton_2d(0, 0xffffffffu), 0xaaaaaaaaaaaaaaaaULL);
}

bool is_fixed_net(const std::vector<pmj02::FixedPoint2>& pts, int count, int m) {
    for (int a = 0; a <= m; ++a) {
        std::vector<uint8_t> seen(size_t(1) << m, 0);
        for (int k = 0; k < count; ++k) {
            uint64_t i = a == 0 ? 0 : pts[size_t(k)].x >> (32 - a);
            uint64_t j = a == m ? 0 : pts[size_t(k)].y >> (32 - (m - a));
            if (seen[size_t((i << (m - a)) + j)]++) return false;
        }
    }
    return true;
}

TEST(Pmj02, EveryPowerOfTwoPrefixIsANet) {
    for (int candidates : {1, 4})
        for (uint64_t seed : {1u, 2u, 3u}) {
            const int n = 1 << 12;
            auto pts = pmj02::generate(n, seed, candidates);
            ASSERT_EQ(int(pts.size()), n);
            for (int m = 0; (1 << m) <= n; ++m)
                EXPECT_TRUE(is_fixed_net(pts, 1 << m, m)) << "prefix 2^" << m << " seed " << seed;
        }
    // The full 2^16 points the pmj02bn sampler uses.
    auto big = pmj02::generate(1 << 16, 9);
    for (int m = 0; m <= 16; ++m) EXPECT_TRUE(is_fixed_net(big, 1 << m, m)) << m;
}

TEST(Pmj02, BlueNoiseTileIsAPermutationWithLittleLowFrequencyEnergy) {
    constexpr int S = pmj02::kBlueNoiseSize, N = S * S;
    auto tile = pmj02::blue_noise_tile(3);
    ASSERT_EQ(int(tile.size()), N);
    std::vector<float> sorted = tile;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < N; ++i) ASSERT_EQ(sorted[size_t(i)], (float(i) + 0.5f) / N);
    // Means of 4 x 4 blocks: white noise of variance 1/12 gives block means of variance 1/(12 16); blue
    // noise, whose energy is at high frequencies, far less.
    double var = 0;
    for (int by = 0; by < S; by += 4)
        for (int bx = 0; bx < S; bx += 4) {
            double m = 0;
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 4; ++x) m += tile[size_t((by + y) * S + bx + x)] / 16.0;
            var += (m - 0.5) * (m - 0.5) / (N / 16);
        }
    const double white = 1.0 / 12 / 16;
    std::printf("  4x4 block-mean variance: %.2e (white noise %.2e)\n", var, white);
    EXPECT_LT(var, white / 4);
}

} // namespace
} // namespace illum
