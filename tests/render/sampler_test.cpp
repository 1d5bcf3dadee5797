// Samplers: range, determinism (DESIGN.md §3), Sobol stratification preserved by Owen scrambling and index
// shuffling, uniformity across pixels, decorrelation between dimensions, and convergence on a smooth
// integrand.
#include "illum/render/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "math/stat_util.h"

namespace illum {
namespace {

constexpr SamplerKind kKinds[] = {SamplerKind::independent, SamplerKind::sobol};

TEST(Sampler, ValuesInUnitInterval) {
    EXPECT_LT(sampling_detail::bits_to_unit_float(0xffffffffu), 1.0f);
    for (SamplerKind kind : kKinds) {
        Sampler s(kind, 64, 5);
        for (int py = -3; py < 20; ++py)
            for (int px = 0; px < 20; ++px)
                for (int i = 0; i < 64; ++i) {
                    s.start_pixel_sample({px, py}, i);
                    Point2f p = s.get_pixel_2d();
                    ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
                    for (int d = 0; d < 8; ++d) {
                        float x = s.get_1d();
                        Point2f q = s.get_2d();
                        ASSERT_TRUE(x >= 0 && x < 1 && q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1);
                    }
                }
    }
}

std::vector<float> draw(Sampler s, Point2i pixel, int index, bool pixel_last = false) {
    s.start_pixel_sample(pixel, index);
    std::vector<float> v;
    if (!pixel_last) {
        Point2f p = s.get_pixel_2d();
        v = {p.x, p.y};
    }
    for (int d = 0; d < 6; ++d) {
        Point2f q = s.get_2d();
        v.insert(v.end(), {s.get_1d(), q.x, q.y});
    }
    if (pixel_last) {
        Point2f p = s.get_pixel_2d();
        v.insert(v.begin(), {p.x, p.y});
    }
    return v;
}

int count_equal(const std::vector<float>& a, const std::vector<float>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] == b[i];
    return n;
}

TEST(Sampler, Deterministic) {
    for (SamplerKind kind : kKinds) {
        SCOPED_TRACE(sampler_kind_name(kind));
        Sampler a(kind, 16, 1), b(kind, 16, 1), c(kind, 16, 2);
        // Same (seed, pixel, index) -> same numbers, whatever was drawn before and in what order the pixel
        // offset is requested.
        draw(a, {9, 9}, 3);
        auto ref = draw(a, {4, 7}, 5);
        EXPECT_EQ(ref, draw(b, {4, 7}, 5));
        EXPECT_EQ(ref, draw(b, {4, 7}, 5, /*pixel_last=*/true));
        // Different seed, pixel or index -> different numbers (a chance equality is 2^-24 per value).
        EXPECT_LE(count_equal(ref, draw(c, {4, 7}, 5)), 1);
        EXPECT_LE(count_equal(ref, draw(a, {5, 7}, 5)), 1);
        EXPECT_LE(count_equal(ref, draw(a, {4, 7}, 6)), 1);
        EXPECT_LE(count_equal(ref, draw(a, {7, 4}, 5)), 1);
    }
    EXPECT_EQ(parse_sampler_kind("sobol"), SamplerKind::sobol);
    EXPECT_EQ(parse_sampler_kind("independent"), SamplerKind::independent);
    EXPECT_EQ(parse_sampler_kind("halton"), SamplerKind::halton);
    EXPECT_FALSE(parse_sampler_kind("sobel").has_value());
}

// Whether points form a (0, k, 2)-net in base 2: every elementary interval [i 2^-a, (i+1) 2^-a) x
// [j 2^-(k-a), (j+1) 2^-(k-a)), a = 0..k, holds exactly one point. a = k and a = 0 are the 1D projections.
bool is_net(const std::vector<Point2f>& pts, int k) {
    const int n = 1 << k;
    for (int a = 0; a <= k; ++a) {
        std::vector<int> count(size_t(n), 0);
        for (Point2f p : pts) {
            int i = int(p.x * float(1 << a)), j = int(p.y * float(1 << (k - a)));
            if (++count[size_t((i << (k - a)) + j)] > 1) return false;
        }
    }
    return true;
}

bool is_stratified_1d(const std::vector<float>& xs, int k) {
    std::vector<int> count(size_t(1) << k, 0);
    for (float x : xs)
        if (++count[size_t(x * float(1 << k))] > 1) return false;
    return true;
}

TEST(Sampler, SobolPixelSamplesAreStratified) {
    Sampler s(SamplerKind::sobol, 1024, 11);
    int checked = 0;
    for (Point2i pixel : {Point2i{0, 0}, Point2i{17, -3}, Point2i{1000, 2000}})
        for (int k = 0; k <= 10; ++k)
            for (int block = 0; block < 2; ++block) { // samples [0, 2^k) and [2^k, 2^(k+1))
                const int first = block << k;
                // dimension 0 is the pixel offset, then dimensions 1..4 in order 2D, 1D, 2D, 1D.
                std::vector<Point2f> pix, d1, d3;
                std::vector<float> d2, d4;
                for (int i = first; i < first + (1 << k); ++i) {
                    s.start_pixel_sample(pixel, i);
                    pix.push_back(s.get_pixel_2d());
                    d1.push_back(s.get_2d());
                    d2.push_back(s.get_1d());
                    d3.push_back(s.get_2d());
                    d4.push_back(s.get_1d());
                }
                SCOPED_TRACE(::testing::Message()
                             << "pixel " << pixel.x << "," << pixel.y << " k " << k << " block " << block);
                EXPECT_TRUE(is_net(pix, k));
                EXPECT_TRUE(is_net(d1, k));
                EXPECT_TRUE(is_net(d3, k));
                EXPECT_TRUE(is_stratified_1d(d2, k));
                EXPECT_TRUE(is_stratified_1d(d4, k));
                ++checked;
            }
    EXPECT_EQ(checked, 66);
}

// Negative control: the stratification check has teeth (64 independent points are stratified with
// probability 64!/64^64 ~ 1e-27).
TEST(Sampler, IndependentIsNotStratified) {
    Sampler s(SamplerKind::independent, 64, 11);
    std::vector<Point2f> pts;
    for (int i = 0; i < 64; ++i) {
        s.start_pixel_sample({3, 4}, i);
        pts.push_back(s.get_2d());
    }
    EXPECT_FALSE(is_net(pts, 6));
}

// For a fixed sample index and dimension, values across pixels are independent uniforms (the hashed
// scrambles randomise them): chi-square in 1D and 2D at 1%.
TEST(Sampler, UniformAcrossPixels) {
    for (SamplerKind kind : kKinds) {
        SCOPED_TRACE(sampler_kind_name(kind));
        Sampler s(kind, 16, 3);
        const int bins = 16, w = 128, h = 128;
        std::vector<double> ox(bins), o1(bins), o2(bins * bins);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                s.start_pixel_sample({x, y}, 5);
                float v1 = s.get_1d();
                Point2f p = s.get_2d();
                ox[size_t(v1 * bins)] += 1;
                o1[size_t(p.x * bins)] += 1;
                o2[size_t(int(p.x * bins) * bins + int(p.y * bins))] += 1;
            }
        std::vector<double> e1(bins, double(w * h) / bins), e2(bins * bins, double(w * h) / (bins * bins));
        for (auto* o : {&ox, &o1}) {
            auto r = test::chi2_test(*o, e1);
            std::printf("  chi2 %.1f dof %d p %.3f\n", r.statistic, r.dof, r.p_value);
            EXPECT_GT(r.p_value, 0.01);
        }
        auto r = test::chi2_test(o2, e2);
        std::printf("  chi2 %.1f dof %d p %.3f\n", r.statistic, r.dof, r.p_value);
        EXPECT_GT(r.p_value, 0.01);
    }
}

struct PixelErrors {
    test::MeanAccumulator error;   // signed error per pixel
    test::MeanAccumulator squared; // squared error per pixel
};

// Per-pixel estimates of ∫∫ f over [0,1)^2 using (first value, second value) from the sampler.
template <typename Draw>
PixelErrors integrate(Sampler s, int spp, double truth, Draw draw) {
    PixelErrors r;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            double sum = 0;
            for (int i = 0; i < spp; ++i) {
                s.start_pixel_sample({x, y}, i);
                sum += draw(s);
            }
            double e = sum / spp - truth;
            r.error.add(e);
            r.squared.add(e * e);
        }
    return r;
}

TEST(Sampler, SobolConvergesFasterOnSmoothIntegrand) {
    // ∫∫ x y = 1/4 over 1024 pixels at 64 spp. Independent: per-pixel variance Var(xy)/64 with
    // Var(xy) = 1/9 - 1/16 = 7/144, so the MSE must match 7/144/64 within 5 standard errors of the MSE
    // estimate. Owen-scrambled Sobol: unbiased (mean error within 5 standard errors) and an RMS error far
    // below independent (for smooth integrands its variance falls like N^-3, not N^-1).
    const int spp = 64;
    auto xy = [](Sampler& s) {
        Point2f p = s.get_2d();
        return double(p.x) * p.y;
    };
    PixelErrors ind = integrate(Sampler(SamplerKind::independent, spp, 1), spp, 0.25, xy);
    PixelErrors sob = integrate(Sampler(SamplerKind::sobol, spp, 1), spp, 0.25, xy);
    const double mse_theory = 7.0 / 144.0 / spp;
    const double rms_ind = std::sqrt(ind.squared.mean), rms_sob = std::sqrt(sob.squared.mean);
    std::printf("  rms error: independent %.3g (theory %.3g), sobol %.3g, ratio %.1f\n", rms_ind,
                std::sqrt(mse_theory), rms_sob, rms_ind / rms_sob);
    EXPECT_NEAR(ind.squared.mean, mse_theory, 5 * ind.squared.std_error());
    EXPECT_NEAR(ind.error.mean, 0.0, 5 * ind.error.std_error());
    EXPECT_NEAR(sob.error.mean, 0.0, 5 * sob.error.std_error());
    EXPECT_LT(rms_sob, rms_ind / 10);
}

// Reference Owen scramble (A. Owen, "Randomly Permuted (t,m,s)-Nets and (t,s)-Sequences", 1995): each
// digit of the 32-bit fraction x is flipped by an independent random bit chosen by the digits above it,
// here a hash of (seed, position, prefix). Slow (32 hashes) but exact, against which the Laine-Karras
// approximation is compared.
uint32_t owen_reference(uint32_t x, uint64_t seed) {
    uint32_t out = x;
    for (int b = 31; b >= 0; --b) {
        uint32_t prefix = b == 31 ? 0u : x >> (b + 1);
        out ^= uint32_t(hash(seed, b, prefix) & 1) << b;
    }
    return out;
}

// Per-pixel errors of ∫∫ x1 x2 = 1/4 where x1, x2 are the first coordinates of two padded dimensions.
// Either the sampler under test, or the same construction with the exact Owen scramble for the index
// shuffle and the values.
PixelErrors cross_dimension_errors(bool reference, int spp) {
    Sampler s(SamplerKind::sobol, spp, 4);
    PixelErrors r;
    for (int p = 0; p < 4096; ++p) {
        double sum = 0;
        for (int i = 0; i < spp; ++i) {
            double a, b;
            if (reference) {
                uint64_t h1 = hash(4, p, 1), h2 = hash(4, p, 2);
                using sampling_detail::sobol_dim0;
                a = owen_reference(sobol_dim0(owen_reference(uint32_t(i), h1)), mix_bits(h1)) * 0x1p-32;
                b = owen_reference(sobol_dim0(owen_reference(uint32_t(i), h2)), mix_bits(h2)) * 0x1p-32;
            } else {
                s.start_pixel_sample({p, 0}, i);
                a = s.get_1d();
                b = s.get_2d().x;
            }
            sum += a * b;
        }
        double e = sum / spp - 0.25;
        r.error.add(e);
        r.squared.add(e * e);
    }
    return r;
}

TEST(Sampler, SobolDimensionsAreDecorrelated) {
    // Two padded dimensions are paired through independent index shuffles. The estimate of E[x1 x2] = 1/4
    // must be unbiased, and its MSE must match that of the exact-Owen construction (within 5 standard
    // errors of the difference). Both 1D projections are stratified, so what is left is the interaction
    // (x1 - 1/2)(x2 - 1/2) of variance 1/144: a uniformly random pairing would give an MSE of 1/(144 N);
    // nested (Owen) pairings measure about 1.6 times that, still O(1/N), i.e. no correlation between
    // dimensions. (A shuffle with the bit order reversed pairs the strata of the two dimensions block by
    // block and gives ~37/(144 N) at N = 64: the test catches that.)
    const int spp = 64;
    PixelErrors got = cross_dimension_errors(false, spp), ref = cross_dimension_errors(true, spp);
    const double random_pairing = 1.0 / 144 / spp;
    std::printf("  cross-dimension mse x 144 N: sampler %.3f, exact Owen %.3f (random pairing 1)\n",
                got.squared.mean / random_pairing, ref.squared.mean / random_pairing);
    EXPECT_NEAR(got.error.mean, 0.0, 5 * got.error.std_error());
    EXPECT_NEAR(got.squared.mean, ref.squared.mean,
                5 * std::hypot(got.squared.std_error(), ref.squared.std_error()));
    EXPECT_LT(got.squared.mean, 3 * random_pairing);

    // The pixel offset against a later dimension: unbiased too.
    auto pix = [](Sampler& s) {
        Point2f p = s.get_pixel_2d();
        s.get_1d();
        return double(p.y) * s.get_2d().y;
    };
    PixelErrors q = integrate(Sampler(SamplerKind::sobol, spp, 4), spp, 0.25, pix);
    EXPECT_NEAR(q.error.mean, 0.0, 5 * q.error.std_error());
    EXPECT_LT(q.squared.mean, 3 * random_pairing);
}

TEST(Sampler, SobolGeneratorMatrix) {
    using namespace sampling_detail;
    // Dimension 1's first points: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
    const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(sobol_dim1(i) * 0x1p-32, expected[i]);
    EXPECT_EQ(sobol_dim0(1) * 0x1p-32, 0.5);
    EXPECT_EQ(sobol_dim0(3) * 0x1p-32, 0.75);
    // The reversed tables give the reversed dimension 1 of the reversed index, for every bit of it.
    for (uint32_t b = 0; b < 32; ++b)
        EXPECT_EQ(sobol_dim1_reversed(reverse_bits(1u << b)), reverse_bits(sobol_dim1(1u << b))) << b;
    PCG32 rng;
    for (int k = 0; k < 10000; ++k) {
        uint32_t i = rng.uniform_uint32();
        ASSERT_EQ(sobol_dim1_reversed(reverse_bits(i)), reverse_bits(sobol_dim1(i))) << i;
    }
    // The nested uniform scramble is a bijection on aligned blocks: the first 2^k indices map onto one
    // aligned block of 2^k indices.
    for (int k = 0; k <= 12; ++k) {
        uint32_t seed = uint32_t(hash(k));
        uint32_t block = nested_uniform_scramble(0, seed) >> k;
        std::vector<bool> seen(size_t(1) << k);
        for (uint32_t i = 0; i < (1u << k); ++i) {
            uint32_t j = nested_uniform_scramble(i, seed);
            ASSERT_EQ(j >> k, block);
            ASSERT_FALSE(seen[j & ((1u << k) - 1)]);
            seen[j & ((1u << k) - 1)] = true;
        }
    }
}

} // namespace
} // namespace illum

namespace illum {
namespace {

TEST(Sampler, DrawsNotReadLeaveTheRestOfTheSequence) {
    // get_1d_if(false) / get_2d_if(false) (a one-lobe BSDF's lobe choice, a pinhole's lens point) pass their
    // dimensions over: every later draw is the one get_1d() / get_2d() would have left, also past halton's
    // last prime, where its dimensions wrap; a draw that is read is get_1d()'s / get_2d()'s.
    for (SamplerKind kind :
         {SamplerKind::independent, SamplerKind::sobol, SamplerKind::zsobol, SamplerKind::paddedsobol,
          SamplerKind::halton, SamplerKind::pmj02bn, SamplerKind::stratified}) {
        Sampler a(kind, 16, 7), b(kind, 16, 7);
        for (int index : {0, 5, 15}) {
            a.start_pixel_sample({3, 4}, index);
            b.start_pixel_sample({3, 4}, index);
            (void)a.get_pixel_2d();
            (void)b.get_pixel_2d();
            for (int k = 0; k < 700; ++k) {
                const bool read = k % 3 == 0;
                const std::string where = std::string(sampler_kind_name(kind)) + " " + std::to_string(index) +
                                          " " + std::to_string(k);
                const float a1 = a.get_1d(), b1 = b.get_1d_if(read);
                if (read) EXPECT_EQ(a1, b1) << where;
                const Point2f a2 = a.get_2d(), b2 = b.get_2d_if(read);
                if (read) EXPECT_EQ(a2.x, b2.x) << where;
                if (read) EXPECT_EQ(a2.y, b2.y) << where;
            }
            EXPECT_EQ(a.get_1d(), b.get_1d()) << sampler_kind_name(kind);
            const Point2f a2 = a.get_2d(), b2 = b.get_2d();
            EXPECT_EQ(a2.x, b2.x) << sampler_kind_name(kind);
            EXPECT_EQ(a2.y, b2.y) << sampler_kind_name(kind);
        }
    }
}

// Dimension 1 in reversed bits from the index by the superset transform (sobol_block.h) equals the
// tabulated map, over every single bit and many random indices.
TEST(SobolBlock, SupersetTransformIsDimensionOne) {
    using namespace sampling_detail;
    for (int b = 0; b < 32; ++b)
        EXPECT_EQ(sobol_dim1_reversed_from_index(1u << b), sobol_dim1_reversed(reverse_bits(1u << b))) << b;
    PCG32 rng(11);
    for (int k = 0; k < 100000; ++k) {
        uint32_t i = rng.uniform_uint32();
        ASSERT_EQ(sobol_dim1_reversed_from_index(i), sobol_dim1_reversed(reverse_bits(i))) << i;
        ASSERT_EQ(reverse_bits(sobol_dim1_reversed_from_index(i)), sobol_dim1(i)) << i;
    }
}

// The vector lanes compute the scalar seeds and draws bit for bit, for random pixels, indices and blocks.
TEST(SobolBlock, VectorLanesAreTheScalarDraws) {
    using namespace sampling_detail;
    if (!sobol_blocks_vectorised()) GTEST_SKIP() << "this processor has no AVX2: blocks are drawn one by one";
    PCG32 rng(5);
    for (int k = 0; k < 20000; ++k) {
        const uint64_t pixel_hash = (uint64_t(rng.uniform_uint32()) << 32) | rng.uniform_uint32();
        const uint32_t reversed_index = k < 64 ? reverse_bits(uint32_t(k)) : rng.uniform_uint32();
        // The sampler's blocks start at multiples of eight (dimension 0 in block 0); odd starts too.
        const uint32_t first = kSobolBlock * (rng.uniform_uint32() % 64) + uint32_t(k & 1);
        SobolBlockSeeds sv, ss;
        sobol_block_seeds_avx2(pixel_hash, first, &sv);
        sobol_block_seeds_scalar(pixel_hash, first, &ss);
        float xv[kSobolBlock], yv[kSobolBlock], xs[kSobolBlock], ys[kSobolBlock];
        sobol_block_avx2(sv, reversed_index, xv, yv);
        sobol_block_scalar(ss, reversed_index, xs, ys);
        for (uint32_t j = 0; j < kSobolBlock; ++j) {
            ASSERT_EQ(sv.index[j], ss.index[j]) << k << " " << j;
            ASSERT_EQ(sv.x[j], ss.x[j]) << k << " " << j;
            ASSERT_EQ(sv.y[j], ss.y[j]) << k << " " << j;
            ASSERT_EQ(xv[j], xs[j]) << k << " " << j;
            ASSERT_EQ(yv[j], ys[j]) << k << " " << j;
            const Point2f p = sobol_owen_2d(pixel_hash, reversed_index, first + j);
            ASSERT_EQ(xs[j], p.x) << k << " " << j;
            ASSERT_EQ(ys[j], p.y) << k << " " << j;
            ASSERT_EQ(xs[j], sobol_owen_1d(pixel_hash, reversed_index, first + j)) << k << " " << j;
        }
    }
}

// The sampler's draws are the per-dimension formulas whichever way it computes them, also when a sample is
// resumed after others have been started (the path tracer's camera packets).
TEST(SobolBlock, SamplerDrawsAreThePerDimensionDraws) {
    using namespace sampling_detail;
    Sampler a(SamplerKind::sobol, 64, 3), other(SamplerKind::sobol, 64, 3);
    for (int index : {0, 1, 37, 63, 200}) {
        const Point2i pixel{5, 9};
        const uint64_t pixel_hash = hash(uint64_t(3), pixel.x, pixel.y);
        const uint32_t rev = reverse_bits(uint32_t(index));
        a.start_pixel_sample(pixel, index);
        uint32_t dim = 1;
        for (int k = 0; k < 40; ++k) {
            if (k == 7) { // suspend, draw another sample on the same sampler, resume
                Sampler::Position p = a.position();
                a.start_pixel_sample({6, 9}, index + 1);
                (void)a.get_2d();
                (void)a.get_1d();
                a.resume(p);
            }
            if (k % 3 == 0) {
                ASSERT_EQ(a.get_1d(), sobol_owen_1d(pixel_hash, rev, dim)) << index << " " << dim;
            } else {
                const Point2f p = a.get_2d(), q = sobol_owen_2d(pixel_hash, rev, dim);
                ASSERT_EQ(p.x, q.x) << index << " " << dim;
                ASSERT_EQ(p.y, q.y) << index << " " << dim;
            }
            ++dim;
        }
        // Dimension 0 once the path has left block 0 (drawn by itself then).
        const Point2f late = a.get_pixel_2d(), q_late = sobol_owen_2d(pixel_hash, rev, 0);
        EXPECT_EQ(late.x, q_late.x);
        EXPECT_EQ(late.y, q_late.y);
        other.start_pixel_sample(pixel, index);
        const Point2f p0 = other.get_pixel_2d(), q0 = sobol_owen_2d(pixel_hash, rev, 0);
        EXPECT_EQ(p0.x, q0.x);
        EXPECT_EQ(p0.y, q0.y);
    }
}

} // namespace
} // namespace illum
