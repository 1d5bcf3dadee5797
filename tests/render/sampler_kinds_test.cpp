// pbrt-v4's samplers (sampler.h): zsobol, paddedsobol, halton, pmj02bn, stratified. Each one's points in a
// pixel are stratified as it claims, values lie in [0, 1), a sample's numbers depend only on (seed,
// pixel, index, dimension), pixels get different sequences, and on a smooth integrand each has a lower
// error than independent sampling at equal N.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "illum/render/low_discrepancy.h"
#include "illum/render/sampler.h"
#include "illum/util/error.h"
#include "math/stat_util.h"

namespace illum {
namespace {

constexpr SamplerKind kNewKinds[] = {SamplerKind::zsobol, SamplerKind::paddedsobol, SamplerKind::halton,
                                     SamplerKind::pmj02bn, SamplerKind::stratified};

SamplerSettings with(Randomization r, Point2i res = {64, 64}) {
    SamplerSettings s;
    s.randomization = r;
    s.resolution = res;
    return s;
}

SamplerSettings at(Point2i res) {
    SamplerSettings s;
    s.resolution = res;
    return s;
}

// Every kind with every randomization it takes.
std::vector<std::pair<SamplerKind, SamplerSettings>> all_configurations() {
    std::vector<std::pair<SamplerKind, SamplerSettings>> out;
    for (Randomization r : {Randomization::none, Randomization::permute_digits, Randomization::fast_owen,
                            Randomization::owen}) {
        out.push_back({SamplerKind::zsobol, with(r)});
        out.push_back({SamplerKind::paddedsobol, with(r)});
        if (r != Randomization::fast_owen) out.push_back({SamplerKind::halton, with(r)});
    }
    out.push_back({SamplerKind::pmj02bn, at({64, 64})});
    out.push_back({SamplerKind::stratified, at({64, 64})});
    SamplerSettings centred = at({64, 64});
    centred.jitter = false;
    out.push_back({SamplerKind::stratified, centred});
    return out;
}

std::string describe(SamplerKind k, const SamplerSettings& s) {
    return std::string(sampler_kind_name(k)) + " " +
           (s.randomization ? std::string(randomization_name(*s.randomization)) : std::string("default")) +
           (s.jitter ? "" : " centred");
}

TEST(SamplerKinds, NamesRoundTrip) {
    for (SamplerKind k : kNewKinds) EXPECT_EQ(parse_sampler_kind(sampler_kind_name(k)), k);
    for (Randomization r :
         {Randomization::none, Randomization::permute_digits, Randomization::fast_owen, Randomization::owen})
        EXPECT_EQ(parse_randomization(randomization_name(r)), r);
    EXPECT_FALSE(parse_randomization("fast-owen").has_value());
    EXPECT_THROW(Sampler(SamplerKind::halton, 16, 0, with(Randomization::fast_owen)), Error);
    EXPECT_THROW(Sampler(SamplerKind::pmj02bn, 65537, 0), Error);
}

TEST(SamplerKinds, ValuesInUnitInterval) {
    for (auto& [kind, settings] : all_configurations()) {
        SCOPED_TRACE(describe(kind, settings));
        for (int spp : {1, 5, 16}) {
            Sampler s(kind, spp, 5, settings);
            for (int py = -3; py < 9; ++py)
                for (int px = 0; px < 9; ++px)
                    for (int i = 0; i < 2 * spp; ++i) { // beyond spp: a time-budget render's later rounds
                        s.start_pixel_sample({px, py}, i);
                        Point2f p = s.get_pixel_2d();
                        ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
                        for (int d = 0; d < 12; ++d) {
                            float x = s.get_1d();
                            Point2f q = s.get_2d();
                            ASSERT_TRUE(x >= 0 && x < 1 && q.x >= 0 && q.x < 1 && q.y >= 0 && q.y < 1)
                                << x << " " << q.x << " " << q.y;
                        }
                    }
        }
    }
    // Halton wraps to dimension 2 after its 1000 prime bases, as pbrt-v4 does.
    Sampler h(SamplerKind::halton, 4, 1, at({8, 8}));
    h.start_pixel_sample({1, 2}, 3);
    for (int d = 0; d < 2100; ++d) {
        float x = h.get_1d();
        ASSERT_TRUE(x >= 0 && x < 1);
    }
}

std::vector<float> draw(Sampler s, Point2i pixel, int index, bool pixel_last = false) {
    s.start_pixel_sample(pixel, index);
    std::vector<float> v;
    if (!pixel_last) {
        Point2f p = s.get_pixel_2d();
        v = {p.x, p.y};
    }
    for (int d = 0; d < 8; ++d) {
        Point2f q = s.get_2d();
        v.insert(v.end(), {s.get_1d(), q.x, q.y});
    }
    if (pixel_last) {
        Point2f p = s.get_pixel_2d();
        v.insert(v.begin(), {p.x, p.y});
    }
    return v;
}

// 20 (2D, 1D) pairs then the pixel offset, from a fresh copy.
std::vector<float> draw_long(Sampler s, Point2i pixel, int index) {
    s.start_pixel_sample(pixel, index);
    std::vector<float> v;
    for (int d = 0; d < 20; ++d) {
        Point2f q = s.get_2d();
        v.insert(v.end(), {s.get_1d(), q.x, q.y});
    }
    Point2f p = s.get_pixel_2d();
    v.insert(v.begin(), {p.x, p.y});
    return v;
}

int count_equal(const std::vector<float>& a, const std::vector<float>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] == b[i];
    return n;
}

TEST(SamplerKinds, DeterministicAndDistinct) {
    for (auto& [kind, settings] : all_configurations()) {
        SCOPED_TRACE(describe(kind, settings));
        // Values drawn at random (not unrandomised digits, not stratum centres) repeat only by chance.
        const bool randomised = !(settings.randomization == Randomization::none) && settings.jitter;
        Sampler a(kind, 16, 1, settings), b(kind, 16, 1, settings), c(kind, 16, 2, settings);
        draw(a, {9, 9}, 3);
        auto ref = draw(a, {4, 7}, 5);
        // Same (seed, pixel, index): same numbers whatever came before and wherever the pixel offset is
        // asked for.
        EXPECT_EQ(ref, draw(b, {4, 7}, 5));
        EXPECT_EQ(ref, draw(b, {4, 7}, 5, /*pixel_last=*/true));
        // Another pixel, index or seed: other numbers. Halton's pixel offset is the unscrambled radical
        // inverse and pmj02bn's comes from a fixed table (both pbrt-v4's), the same for every seed; an
        // unrandomised sequence may repeat a value between pixels.
        const int allowed = kind == SamplerKind::halton || kind == SamplerKind::pmj02bn ? 2 : 1;
        if (randomised) {
            EXPECT_LE(count_equal(ref, draw(a, {5, 7}, 5)), allowed);
            EXPECT_LE(count_equal(ref, draw(a, {4, 7}, 6)), allowed);
            EXPECT_LE(count_equal(ref, draw(a, {7, 4}, 5)), allowed);
            EXPECT_LE(count_equal(ref, draw(c, {4, 7}, 5)), allowed); // another seed
        }
        EXPECT_NE(ref, draw(a, {5, 7}, 5));
        EXPECT_NE(ref, draw(a, {4, 7}, 6));
    }
}

// One sampler drawing many samples in the render loop's order (a pixel's samples one after another, which
// zsobol's per-pixel cache serves) and in a shuffled order gives each (pixel, index) the numbers a fresh
// sampler gives it.
TEST(SamplerKinds, SameNumbersInAnyOrder) {
    for (auto& [kind, settings] : all_configurations()) {
        SCOPED_TRACE(describe(kind, settings));
        const Sampler proto(kind, 8, 11, settings);
        Sampler running = proto;
        std::vector<std::pair<Point2i, int>> order;
        for (int p = 0; p < 6; ++p)
            for (int i = 0; i < 8; ++i) order.push_back({{p % 3, p / 3}, i});
        for (int k = 0; k < 48; ++k) order.push_back({{(k * 5) % 3, (k * 7) % 2}, (k * 3) % 8}); // shuffled
        for (auto [pixel, i] : order) {
            running.start_pixel_sample(pixel, i);
            std::vector<float> got;
            for (int d = 0; d < 20; ++d) { // beyond zsobol's 32 cached dimensions too
                Point2f q = running.get_2d();
                got.insert(got.end(), {running.get_1d(), q.x, q.y});
            }
            Point2f px = running.get_pixel_2d();
            got.insert(got.begin(), {px.x, px.y});
            ASSERT_EQ(got, draw_long(proto, pixel, i)) << pixel.x << "," << pixel.y << " " << i;
        }
    }
}

// No two pixels of a 32 x 32 image get the same sequence (their first 8 samples of 26 values each).
TEST(SamplerKinds, PixelsGetDifferentSequences) {
    for (auto& [kind, settings] : all_configurations()) {
        SCOPED_TRACE(describe(kind, settings));
        SamplerSettings st = settings;
        st.resolution = {32, 32};
        Sampler s(kind, 8, 3, st);
        std::set<std::vector<float>> seen;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                std::vector<float> seq;
                for (int i = 0; i < 8; ++i) {
                    auto v = draw(s, {x, y}, i);
                    seq.insert(seq.end(), v.begin(), v.end());
                }
                EXPECT_TRUE(seen.insert(seq).second) << x << "," << y;
            }
    }
}

// Whether points form a (0, k, 2)-net in base 2: every elementary interval of area 2^-k holds one point.
bool is_net(const std::vector<Point2f>& pts, int k) {
    const int n = 1 << k;
    if (int(pts.size()) != n) return false;
    for (int a = 0; a <= k; ++a) {
        std::vector<int> count(size_t(n), 0);
        for (Point2f p : pts) {
            int i = int(p.x * float(1 << a)), j = int(p.y * float(1 << (k - a)));
            if (++count[size_t((i << (k - a)) + j)] > 1) return false;
        }
    }
    return true;
}

bool is_stratified_1d(const std::vector<float>& xs, int strata) {
    std::vector<int> count(size_t(strata), 0);
    for (float x : xs)
        if (++count[size_t(x * float(strata))] > 1) return false;
    return true;
}

struct PixelPoints {
    std::vector<Point2f> pixel, d2a, d2b;
    std::vector<float> d1a, d1b;
};

PixelPoints pixel_points(Sampler s, Point2i pixel, int first, int count) {
    PixelPoints p;
    for (int i = first; i < first + count; ++i) {
        s.start_pixel_sample(pixel, i);
        p.pixel.push_back(s.get_pixel_2d());
        p.d2a.push_back(s.get_2d());
        p.d1a.push_back(s.get_1d());
        p.d2b.push_back(s.get_2d());
        p.d1b.push_back(s.get_1d());
    }
    return p;
}

TEST(SamplerKinds, ZSobolPixelIsANetAndSoIsA2x2Block) {
    for (Randomization r :
         {Randomization::none, Randomization::permute_digits, Randomization::fast_owen, Randomization::owen})
        for (int k : {2, 4, 5, 6}) {
            SCOPED_TRACE(::testing::Message() << randomization_name(r) << " spp 2^" << k);
            Sampler s(SamplerKind::zsobol, 1 << k, 7, with(r, {64, 48}));
            for (Point2i px : {Point2i{0, 0}, Point2i{13, 5}, Point2i{63, 47}}) {
                PixelPoints p = pixel_points(s, px, 0, 1 << k);
                EXPECT_TRUE(is_net(p.pixel, k));
                EXPECT_TRUE(is_net(p.d2a, k));
                EXPECT_TRUE(is_net(p.d2b, k));
                EXPECT_TRUE(is_stratified_1d(p.d1a, 1 << k));
                EXPECT_TRUE(is_stratified_1d(p.d1b, 1 << k));
                // Prefixes made of whole digits are nets too: 4^j samples, or 2 4^j for odd k.
                for (int j = 2 - (k & 1); j < k; j += 2)
                    EXPECT_TRUE(is_net(pixel_points(s, px, 0, 1 << j).d2a, j));
            }
            // Ahmed & Wonka's hierarchy: the 4 spp samples of an aligned 2 x 2 block of pixels are one
            // aligned block of Sobol indices, a (0, k + 2, 2)-net (in every dimension).
            std::vector<Point2f> block;
            for (Point2i px : {Point2i{10, 6}, Point2i{11, 6}, Point2i{10, 7}, Point2i{11, 7}}) {
                PixelPoints p = pixel_points(s, px, 0, 1 << k);
                block.insert(block.end(), p.d2b.begin(), p.d2b.end());
            }
            EXPECT_TRUE(is_net(block, k + 2));
        }
}

TEST(SamplerKinds, PaddedSobolPixelIsANet) {
    for (Randomization r :
         {Randomization::none, Randomization::permute_digits, Randomization::fast_owen, Randomization::owen})
        for (int k : {0, 3, 4, 7}) {
            SCOPED_TRACE(::testing::Message() << randomization_name(r) << " spp 2^" << k);
            Sampler s(SamplerKind::paddedsobol, 1 << k, 3, with(r));
            for (Point2i px : {Point2i{0, 0}, Point2i{-4, 9}, Point2i{1000, 3}}) {
                PixelPoints p = pixel_points(s, px, 0, 1 << k);
                EXPECT_TRUE(is_net(p.pixel, k));
                EXPECT_TRUE(is_net(p.d2a, k));
                EXPECT_TRUE(is_net(p.d2b, k));
                EXPECT_TRUE(is_stratified_1d(p.d1a, 1 << k));
                // A later round (indices spp .. 2 spp - 1) is another net.
                EXPECT_TRUE(is_net(pixel_points(s, px, 1 << k, 1 << k).d2a, k));
            }
        }
}

TEST(SamplerKinds, StratifiedOnePointPerStratum) {
    for (bool jitter : {true, false})
        for (auto [xs, ys] : {std::pair{4, 4}, std::pair{3, 5}, std::pair{1, 7}}) {
            SCOPED_TRACE(::testing::Message() << xs << "x" << ys << (jitter ? " jittered" : " centred"));
            SamplerSettings st;
            st.x_samples = xs, st.y_samples = ys, st.jitter = jitter;
            const int n = xs * ys;
            Sampler s(SamplerKind::stratified, n, 9, st);
            for (Point2i px : {Point2i{2, 3}, Point2i{40, -1}}) {
                PixelPoints p = pixel_points(s, px, 0, n);
                for (const auto* pts : {&p.pixel, &p.d2a, &p.d2b}) {
                    std::vector<int> count(size_t(n), 0);
                    for (Point2f q : *pts) {
                        int cx = int(q.x * xs), cy = int(q.y * ys);
                        ++count[size_t(cy * xs + cx)];
                        if (!jitter) { // the stratum's centre
                            EXPECT_FLOAT_EQ(q.x, (cx + 0.5f) / xs);
                            EXPECT_FLOAT_EQ(q.y, (cy + 0.5f) / ys);
                        }
                    }
                    for (int c : count) EXPECT_EQ(c, 1);
                }
                EXPECT_TRUE(is_stratified_1d(p.d1a, n));
                EXPECT_TRUE(is_stratified_1d(p.d1b, n));
            }
        }
    // spp that is not xsamples x ysamples (the CLI's --spp) is factored as pbrt-v4 does: 12 = 4 x 3.
    SamplerSettings st;
    st.x_samples = st.y_samples = 4;
    Sampler s(SamplerKind::stratified, 12, 1, st);
    PixelPoints p = pixel_points(s, {0, 0}, 0, 12);
    std::vector<int> count(12, 0);
    for (Point2f q : p.d2a) ++count[size_t(int(q.y * 3) * 4 + int(q.x * 4))];
    for (int c : count) EXPECT_EQ(c, 1);
}

TEST(SamplerKinds, HaltonMapsSamplesToTheirPixel) {
    // Resolution 5 x 7: scales 2^3 = 8 and 3^2 = 9. With no randomization the pixel offset and the
    // dimensions are plain radical inverses of one global index h: pixel x = floor(8 Φ_2(h)), y =
    // floor(9 Φ_3(h)), the offset in the pixel 8 Φ_2(h) - x (and likewise in y), dimension 2 Φ_5(h).
    Sampler s(SamplerKind::halton, 16, 0, with(Randomization::none, {5, 7}));
    using low_discrepancy::radical_inverse;
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 5; ++x)
            for (int i = 0; i < 16; ++i) {
                s.start_pixel_sample({x, y}, i);
                Point2f off = s.get_pixel_2d();
                float d2 = s.get_1d();
                // Recover h: the unique index with these digits, in [i 72, (i + 1) 72).
                int found = 0;
                for (uint64_t h = uint64_t(i) * 72; h < uint64_t(i + 1) * 72; ++h) {
                    double u = radical_inverse(0, h), v = radical_inverse(1, h);
                    if (int(u * 8) != x || int(v * 9) != y) continue;
                    ++found;
                    EXPECT_NEAR(off.x, u * 8 - x, 1e-5);
                    EXPECT_NEAR(off.y, v * 9 - y, 1e-5);
                    EXPECT_EQ(d2, radical_inverse(2, h));
                }
                ASSERT_EQ(found, 1) << x << "," << y << " " << i;
            }
    // Hand-computed radical inverses: 6 = 110_2 -> 0.011_2; 5 = 12_3 -> 0.21_3 = 7/9; 7 = 12_5 -> 0.21_5 =
    // 11/25; 1000 in base 7 = 2626_7 -> 0.6262_7.
    EXPECT_EQ(radical_inverse(0, 6), 0.375f);
    EXPECT_FLOAT_EQ(radical_inverse(1, 5), 7.0f / 9);
    EXPECT_FLOAT_EQ(radical_inverse(2, 7), 11.0f / 25);
    EXPECT_FLOAT_EQ(radical_inverse(3, 1000), float(6.0 / 7 + 2.0 / 49 + 6.0 / 343 + 2.0 / 2401));
}

TEST(SamplerKinds, HaltonDimensionsAreStratifiedInTheirBase) {
    // A pixel's samples step the global index by 2^j 3^k, coprime to 5 and 7: 25 samples fill the 25
    // strata of dimension 2 (base 5) and 49 fill dimension 3's (base 7), permuted digits or not.
    for (Randomization r : {Randomization::none, Randomization::permute_digits, Randomization::owen}) {
        SCOPED_TRACE(randomization_name(r));
        Sampler s(SamplerKind::halton, 49, 4, with(r, {40, 30}));
        for (Point2i px : {Point2i{0, 0}, Point2i{17, 29}}) {
            std::vector<float> d2, d3;
            for (int i = 0; i < 49; ++i) {
                s.start_pixel_sample(px, i);
                float a = s.get_1d(), b = s.get_1d();
                if (i < 25) d2.push_back(a);
                d3.push_back(b);
            }
            EXPECT_TRUE(is_stratified_1d(d2, 25));
            EXPECT_TRUE(is_stratified_1d(d3, 49));
        }
    }
}

TEST(SamplerKinds, Pmj02bnPixelOffsetsAreProgressiveNets) {
    for (int spp : {4, 16, 64}) {
        Sampler s(SamplerKind::pmj02bn, spp, 0);
        for (Point2i px : {Point2i{0, 0}, Point2i{5, 3}, Point2i{31, 30}}) {
            PixelPoints p = pixel_points(s, px, 0, spp);
            for (int k = 0; (1 << k) <= spp; ++k) {
                std::vector<Point2f> prefix(p.pixel.begin(), p.pixel.begin() + (1 << k));
                EXPECT_TRUE(is_net(prefix, k)) << "spp " << spp << " prefix 2^" << k;
            }
            EXPECT_TRUE(is_stratified_1d(p.d1a, spp));
            EXPECT_TRUE(is_stratified_1d(p.d1b, spp));
        }
    }
}

// ∫∫ f over [0,1)^2 with f smooth, estimated per pixel from one 2D dimension: RMS error over 1024 pixels.
struct Errors {
    test::MeanAccumulator error, squared;
};

template <typename F>
Errors integrate(const Sampler& proto, int spp, double truth, F f) {
    Errors r;
    Sampler s = proto;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            double sum = 0;
            for (int i = 0; i < spp; ++i) {
                s.start_pixel_sample({x, y}, i);
                s.get_1d();
                Point2f p = s.get_2d();
                sum += f(p.x, p.y);
            }
            double e = sum / spp - truth;
            r.error.add(e);
            r.squared.add(e * e);
        }
    return r;
}

TEST(SamplerKinds, LowerErrorThanIndependentOnASmoothIntegrand) {
    // ∫∫ x y² = 1/6 from 256 samples per pixel over 256 pixels. Independent's MSE is Var(x y²)/256 =
    // (1/15 - 1/36)/256; each low-discrepancy sampler must be unbiased (mean error within 5 standard
    // errors) and at least 3 times more accurate in RMS error (Cranley-Patterson rotated pmj02bn and
    // Halton in bases 7 and 11 converge like 1/N, the Owen-scrambled Sobol samplers faster still).
    const int spp = 256;
    auto f = [](double x, double y) { return x * y * y; };
    const double truth = 1.0 / 6;
    Errors ind = integrate(Sampler(SamplerKind::independent, spp, 1), spp, truth, f);
    const double mse_theory = (1.0 / 15 - 1.0 / 36) / spp;
    EXPECT_NEAR(ind.squared.mean, mse_theory, 5 * ind.squared.std_error());
    const double rms_ind = std::sqrt(ind.squared.mean);
    for (SamplerKind k : kNewKinds) {
        Errors e = integrate(Sampler(k, spp, 1, at({16, 16})), spp, truth, f);
        const double rms = std::sqrt(e.squared.mean);
        std::printf("  %-12s rms error %.3g (independent %.3g, ratio %.1f)\n",
                    std::string(sampler_kind_name(k)).c_str(), rms, rms_ind, rms_ind / rms);
        EXPECT_NEAR(e.error.mean, 0.0, 5 * e.error.std_error() + 1e-7) << sampler_kind_name(k);
        EXPECT_LT(rms, rms_ind / 3) << sampler_kind_name(k);
    }
}

// For a fixed index and dimension, values across the pixels of a 64 x 64 image are uniform: chi-square in
// 1D and 2D at 1%. (pmj02bn's blue-noise tiles repeat every 64 pixels, so a larger image would count each
// value several times.)
TEST(SamplerKinds, UniformAcrossPixels) {
    for (SamplerKind kind : kNewKinds) {
        SCOPED_TRACE(sampler_kind_name(kind));
        Sampler s(kind, 16, 3, at({64, 64}));
        const int bins = 16, w = 64, h = 64;
        std::vector<double> o1(bins), o2(bins * bins);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                s.start_pixel_sample({x, y}, 5);
                o1[size_t(s.get_1d() * bins)] += 1;
                Point2f p = s.get_2d();
                o2[size_t(int(p.x * bins) * bins + int(p.y * bins))] += 1;
            }
        std::vector<double> e1(bins, double(w * h) / bins), e2(bins * bins, double(w * h) / (bins * bins));
        auto r1 = test::chi2_test(o1, e1), r2 = test::chi2_test(o2, e2);
        std::printf("  %s: chi2 1D %.1f (p %.3f), 2D %.1f (p %.3f)\n",
                    std::string(sampler_kind_name(kind)).c_str(), r1.statistic, r1.p_value, r2.statistic,
                    r2.p_value);
        EXPECT_GT(r1.p_value, 0.01);
        EXPECT_GT(r2.p_value, 0.01);
    }
}

} // namespace
} // namespace illum
