// The MIP pyramid and its four filters (texture/mipmap.h): levels are box averages with the image's mean
// and cost at most a third of the image; point, bilinear and trilinear pick levels by the footprint as
// pbrt-v4 does; EWA equals its definition (the Gaussian-weighted sum over the ellipse) computed by brute
// force, blurs only along the footprint's long axis, and tends to the mean for large footprints.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "illum/math/rng.h"
#include "illum/texture/mipmap.h"
#include "illum/texture/pbrt_textures.h"

namespace illum {
namespace {

std::shared_ptr<const Image> checkerboard(int w, int h, int check) {
    auto im = std::make_shared<Image>(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) (*im)(x, y) = Color3(((x / check + y / check) & 1) ? 1.0f : 0.0f);
    return im;
}

std::shared_ptr<const Image> random_image(int w, int h, std::uint64_t seed) {
    auto im = std::make_shared<Image>(w, h);
    PCG32 rng(seed);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            (*im)(x, y) = Color3{rng.uniform_float(), rng.uniform_float(), rng.uniform_float()};
    return im;
}

double mean_r(const Image& im) {
    double s = 0;
    for (int y = 0; y < im.height(); ++y)
        for (int x = 0; x < im.width(); ++x) s += im(x, y).r;
    return s / double(im.pixel_count());
}

TEST(MipPyramid, EvenLevelsAreTwoByTwoAverages) {
    auto im = random_image(16, 8, 1);
    MipPyramid p(im);
    ASSERT_EQ(p.levels(), 5); // 16x8, 8x4, 4x2, 2x1, 1x1
    const Image& l1 = p.level(1);
    ASSERT_EQ(l1.width(), 8);
    ASSERT_EQ(l1.height(), 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            Color3 avg = ((*im)(2 * x, 2 * y) + (*im)(2 * x + 1, 2 * y) + (*im)(2 * x, 2 * y + 1) +
                          (*im)(2 * x + 1, 2 * y + 1)) *
                         0.25f;
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(l1(x, y)[c], avg[c], 1e-6f);
        }
    EXPECT_EQ(p.level(4).width(), 1);
    EXPECT_EQ(p.level(4).height(), 1);
}

TEST(MipPyramid, OddSizesKeepTheMeanAtEveryLevel) {
    for (auto [w, h] : {std::pair{255, 129}, {7, 5}, {300, 3}, {1, 9}}) {
        auto im = random_image(w, h, 7);
        MipPyramid p(im);
        double m0 = mean_r(*im);
        for (int k = 1; k < p.levels(); ++k) {
            const Image& l = p.level(k);
            EXPECT_EQ(l.width(), std::max(1, p.level(k - 1).width() / 2));
            EXPECT_EQ(l.height(), std::max(1, p.level(k - 1).height() / 2));
            EXPECT_NEAR(mean_r(l), m0, 1e-5) << w << "x" << h << " level " << k;
        }
        EXPECT_EQ(p.level(p.levels() - 1).pixel_count(), 1u);
    }
}

TEST(MipPyramid, CostsAtMostAThirdMore) {
    // Σ_k ⌊w/2^k⌋⌊h/2^k⌋ ≤ wh/3 beyond the image, plus the levels after the shorter side reached one
    // texel (at most 2 max/min texels).
    for (auto [w, h] : {std::pair{256, 256}, {255, 255}, {300, 200}, {513, 257}, {64, 1000}, {1024, 3}}) {
        MipPyramid p(checkerboard(w, h, 1));
        double image = double(w) * h;
        double bound = image / 3 + 2.0 * std::max(w, h) / std::min(w, h);
        EXPECT_LE(double(p.extra_texels()), bound) << w << "x" << h;
    }
    MipPyramid square(checkerboard(256, 256, 1));
    EXPECT_LE(double(square.extra_texels()) / (256.0 * 256.0), 1.0 / 3.0);
}

// A footprint whose width in texels of level 0 is `texels` (both axes along s).
Vector2f axis(float texels, int res) { return {texels / float(res), 0}; }

TEST(MipMap, ZeroFootprintReadsTheImage) {
    auto im = random_image(32, 32, 3);
    auto pyr = std::make_shared<const MipPyramid>(im);
    for (MipFilter f : {MipFilter::Point, MipFilter::Bilinear, MipFilter::Trilinear, MipFilter::EWA}) {
        MipMap m(pyr, f, WrapMode::Repeat, 8);
        // At a texel's centre every filter gives that texel.
        Point2f st{(5 + 0.5f) / 32, (9 + 0.5f) / 32};
        Color3 c = m.filter(st, {0, 0}, {0, 0});
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], (*im)(5, 9)[k], 1e-5f) << int(f);
    }
}

TEST(MipMap, LargeFootprintsGiveTheMean) {
    // One-texel checks: level 1 and above are 0.5 exactly.
    auto pyr = std::make_shared<const MipPyramid>(checkerboard(64, 64, 1));
    for (MipFilter f : {MipFilter::Point, MipFilter::Bilinear, MipFilter::Trilinear, MipFilter::EWA})
        for (float texels : {4.0f, 16.0f, 200.0f}) {
            MipMap m(pyr, f, WrapMode::Repeat, 8);
            Color3 c = m.filter({0.3f, 0.7f}, axis(texels, 64), {0, texels / 64});
            EXPECT_NEAR(c.r, 0.5f, 1e-5f) << int(f) << " " << texels;
        }
}

TEST(MipMap, LevelsAreChosenAsPbrtV4Does) {
    auto im = random_image(64, 64, 11);
    auto pyr = std::make_shared<const MipPyramid>(im);
    MipMap point(pyr, MipFilter::Point, WrapMode::Repeat, 8);
    MipMap bilinear(pyr, MipFilter::Bilinear, WrapMode::Repeat, 8);
    MipMap trilinear(pyr, MipFilter::Trilinear, WrapMode::Repeat, 8);
    Point2f st{0.37f, 0.61f};
    // width = 2 max|component| = 2 · 3/64: level log2(6) = 2.585.
    Vector2f d0 = axis(3, 64), d1{0, 1.0f / 64};
    float level = std::log2(6.0f);
    const Image& l2 = pyr->level(2);
    Color3 p = point.filter(st, d0, d1);
    Color3 expect_p = l2(int(std::round(st.x * 16 - 0.5f)), int(std::round(st.y * 16 - 0.5f)));
    EXPECT_NEAR(p.g, expect_p.g, 1e-6f);
    EXPECT_NEAR(bilinear.filter(st, d0, d1).g, bilinear.bilerp(2, st).g, 1e-6f);
    float f = level - 2;
    float tri = (1 - f) * bilinear.bilerp(2, st).g + f * bilinear.bilerp(3, st).g;
    EXPECT_NEAR(trilinear.filter(st, d0, d1).g, tri, 1e-5f);
}

// EWA by its definition: Σ w(Q) texel / Σ w(Q) over every texel of the level (repeat wrapping taken by
// summing over enough periods), w = e^{-2Q} - e^{-2} exactly, Q the widened ellipse's quadratic form.
double ewa_brute_force(const Image& level, Point2f st, Vector2f a0, Vector2f a1) {
    const int w = level.width(), h = level.height();
    double s = st.x * w - 0.5, t = st.y * h - 0.5;
    double a0s = a0.x * w, a0t = a0.y * h, a1s = a1.x * w, a1t = a1.y * h;
    double A = a0t * a0t + a1t * a1t + 1, B = -2 * (a0s * a0t + a1s * a1t), C = a0s * a0s + a1s * a1s + 1;
    double F = A * C - B * B / 4;
    double sum = 0, sum_w = 0;
    for (int it = -2 * h; it < 3 * h; ++it)
        for (int is = -2 * w; is < 3 * w; ++is) {
            double ds = is - s, dt = it - t;
            double q = (A * ds * ds + B * ds * dt + C * dt * dt) / F;
            if (q >= 1) continue;
            double wt = std::exp(-2 * q) - std::exp(-2.0);
            sum += wt * level(((is % w) + w) % w, ((it % h) + h) % h).r;
            sum_w += wt;
        }
    return sum / sum_w;
}

TEST(MipMap, EwaMatchesItsDefinitionForAnAnisotropicFootprint) {
    auto im = random_image(64, 64, 5);
    auto pyr = std::make_shared<const MipPyramid>(im);
    MipMap m(pyr, MipFilter::EWA, WrapMode::Repeat, 8);
    // A sheared ellipse 4:1, minor axis 1.6 texels of level 0: level log2(1.6) = 0.678, between 0 and 1.
    Vector2f a0{6.0f / 64, 2.5f / 64}, a1{-0.6f / 64, 1.48f / 64};
    for (Point2f st : {Point2f{0.41f, 0.27f}, Point2f{0.02f, 0.97f}}) { // the second wraps around
        float minor = std::sqrt(a1.x * a1.x + a1.y * a1.y) * 64;
        float lod = std::log2(minor);
        int il = int(std::floor(lod));
        double expect = (1 - (lod - il)) * ewa_brute_force(pyr->level(il), st, a0, a1) +
                        (lod - il) * ewa_brute_force(pyr->level(il + 1), st, a0, a1);
        // The weights are tabulated at 128 values of Q (a relative step of at most 1/64 in the weight).
        EXPECT_NEAR(m.filter(st, a0, a1).r, expect, 0.01) << st.x;
        EXPECT_NEAR(m.ewa(il, st, a0, a1).r, ewa_brute_force(pyr->level(il), st, a0, a1), 0.01);
    }
}

TEST(MipMap, EwaBlursAlongTheLongAxisOnly) {
    // 256² image of 0.5 + 0.5 cos(2π 4 s): constant along t.
    const int n = 256;
    auto im = std::make_shared<Image>(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            (*im)(x, y) = Color3(0.5f + 0.5f * std::cos(2 * kPi * 4 * (x + 0.5f) / n));
    auto pyr = std::make_shared<const MipPyramid>(im);
    MipMap m(pyr, MipFilter::EWA, WrapMode::Repeat, 8);
    MipMap tri(pyr, MipFilter::Trilinear, WrapMode::Repeat, 8);
    const float s0 = 0.0f; // a crest: value 1
    // Long axis along t (0.1, 25 texels), short along s (3 texels): the crest stays near 1.
    Vector2f along_t{0, 0.1f}, short_s{3.0f / n, 0};
    float v = m.filter({s0, 0.5f}, along_t, short_s).r;
    EXPECT_GT(v, 0.97f);
    // Trilinear blurs isotropically over the long axis: the crest drops to the mean.
    EXPECT_LT(tri.filter({s0, 0.5f}, along_t, short_s).r, 0.8f);
    // Long axis along s spanning a period, short along t: the mean.
    Vector2f along_s{0.25f, 0}, short_t{0, 0.25f / 8};
    EXPECT_NEAR(m.filter({s0, 0.5f}, along_s, short_t).r, 0.5f, 0.05f);
}

TEST(MipMap, MaxAnisotropyWidensTheShortAxis) {
    auto im = random_image(128, 128, 9);
    auto pyr = std::make_shared<const MipPyramid>(im);
    MipMap m2(pyr, MipFilter::EWA, WrapMode::Repeat, 2);
    Vector2f a0{16.0f / 128, 0}, a1{0, 1.0f / 128}, a1_wide{0, 8.0f / 128};
    MipMap m16(pyr, MipFilter::EWA, WrapMode::Repeat, 16);
    Point2f st{0.5f, 0.5f};
    // With maxanisotropy 2 the 16:1 footprint is filtered as 16:8.
    EXPECT_NEAR(m2.filter(st, a0, a1).r, m16.filter(st, a0, a1_wide).r, 1e-6f);
}

TEST(MipMap, WrapModes) {
    auto im = random_image(8, 8, 2);
    auto pyr = std::make_shared<const MipPyramid>(im);
    MipMap repeat(pyr, MipFilter::Point, WrapMode::Repeat, 8),
        clamp(pyr, MipFilter::Point, WrapMode::Clamp, 8), black(pyr, MipFilter::Point, WrapMode::Black, 8);
    EXPECT_EQ(repeat.texel(0, -1, 3), (*im)(7, 3));
    EXPECT_EQ(clamp.texel(0, -1, 3), (*im)(0, 3));
    EXPECT_EQ(black.texel(0, -1, 3), Color3(0.0f));
    EXPECT_EQ(repeat.texel(0, 9, 10), (*im)(1, 2));
}

// pbrt-v4's filtered checkerboard: the tent-filtered square wave against a numerical integral.
TEST(CheckerboardFilter, WaveIsTheTentFilteredSquareWave) {
    auto wave = [](double x) { return (int(std::floor(x)) & 1) ? -1.0 : 1.0; };
    for (float r : {0.3f, 0.8f, 1.7f})
        for (float x : {0.1f, 0.5f, 0.95f, 2.3f, -1.4f}) {
            // ∫ wave(x + u) tent(u / r) / r du, tent(z) = max(0, 1 - |z|).
            const int n = 20000;
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                double u = -r + (i + 0.5) * 2 * r / n;
                sum += wave(x + u) * (1 - std::abs(u) / r) / r * (2 * r / n);
            }
            EXPECT_NEAR(checker_wave_filtered(x, r), sum, 2e-3) << x << " " << r;
        }
    EXPECT_EQ(checker_wave_filtered(0.5f, 0), 1.0f);
    EXPECT_EQ(checker_wave_filtered(1.5f, 0), -1.0f);
    // A wide filter averages the wave to nearly 0.
    EXPECT_NEAR(checker_wave_filtered(0.3f, 40.0f), 0.0f, 0.01f);
}

} // namespace
} // namespace illum
