// Every scene in ../shared/scenes renders from its test.pbrt and matches pbrt-v4's render (refs/spectral/)
// and, where one exists, the converged RGB reference (refs/rgb/).
//
// Tolerances. Each scene is rendered twice with independent seeds (A, B). The noise of a channel mean is
// estimated from the pixels: Var(pixel) ≈ (A - B)² / 2, and the mean of the average (A + B)/2 has
// σ = sqrt(mean((A - B)²/2) / (2N)). A channel mean must then be within (bound + 4.5 σ) of the reference
// mean, where `bound` is the systematic difference allowed between illum's RGB rendering and the
// reference:
//   - against an RGB reference: 1% (RGB renderers agree within 0.05%; the acceptance asks for 2%);
//   - against pbrt-v4 (spectral): 2.5% for neutral channels; for saturated ones the difference that
//     spectral rendering itself makes (refs/README.md: Cornell box B 3.9% below RGB renderers; orange
//     plastic R 17% below): 6% for the Cornell boxes' blue, 12% for coffee's red, 5% for its G and B.
//     These bounds are upper limits for the documented spectral/RGB difference, not fitted to illum:
//     the measured figures are printed and recorded in docs/scenes.md.
// Per pixel, against a reference at the same resolution: d = (A - ref)² - (A - B)²/2 averages to zero
// for an unbiased render (see tests/reference/cornell_box_test.cpp); it is asserted against the RGB
// reference and printed (as the ratio MSE(A, ref) / noise) against the spectral ones.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "illum/image/image_io.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "test_support.h"

namespace illum {
namespace {

struct SceneCase {
    const char* name;
    int spp;
    Color3 bound; // allowed systematic difference from refs/spectral, per channel (fraction)
};

const SceneCase kCases[] = {
    {"cornell-box", 16, {0.025f, 0.025f, 0.06f}},
    {"cornell-box-measured", 16, {0.025f, 0.025f, 0.06f}},
    {"veach-mis", 32, {0.025f, 0.025f, 0.025f}},
    {"coffee", 32, {0.12f, 0.05f, 0.05f}},
};

void PrintTo(const SceneCase& c, std::ostream* os) { *os << c.name; }

Image render_scene(const std::string& name, int spp, std::uint64_t seed, int resolution = 0,
                   bool spectral = false) {
    return test::render_shared_scene(name, spp, seed, resolution, spectral);
}

using test::pixel_check;
using test::PixelCheck;

class SharedScene : public testing::TestWithParam<SceneCase> {
protected:
    void SetUp() override {
        if (!test::have_shared()) GTEST_SKIP() << "shared dir absent: " << test::shared_dir();
    }
};

TEST_P(SharedScene, MatchesPbrtV4) {
    const SceneCase& c = GetParam();
    Image ref = read_image(test::shared_dir() + "/refs/spectral/" + c.name + ".exr");
    auto t0 = std::chrono::steady_clock::now();
    Image a = render_scene(c.name, c.spp, 1), b = render_scene(c.name, c.spp, 2);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(a.width(), ref.width());
    ASSERT_EQ(a.height(), ref.height());
    Color3 ma = a.channel_mean(), mb = b.channel_mean(), mr = ref.channel_mean();
    std::printf("%s: %dx%d, 2 x %d spp in %.1f s\n", c.name, a.width(), a.height(), c.spp, secs);
    for (int ch = 0; ch < 3; ++ch) {
        PixelCheck k = pixel_check(a, b, ref, ch);
        double m = 0.5 * (ma[ch] + mb[ch]);
        double diff = m / mr[ch] - 1, sigma = k.mean_sigma / mr[ch];
        std::printf(
            "  channel %d: mean %.6f, pbrt-v4 %.6f, difference %+.2f%% (noise sigma %.2f%%, bound %.1f%%); "
            "per-pixel MSE vs pbrt-v4 / noise = %.3f\n",
            ch, m, mr[ch], 100 * diff, 100 * sigma, 100 * c.bound[ch], k.mse_ref / k.mse_noise);
        EXPECT_LT(std::abs(diff), c.bound[ch] + 4.5 * sigma) << c.name << " channel " << ch;
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, SharedScene, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<SceneCase>& i) {
                             std::string n = i.param.name;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

// Spectral mode renders what pbrt-v4 renders: the same uplifting of RGB inputs, the same spectra, the same
// XYZ film. Each channel mean within 1% of pbrt-v4's + 4.5 σ (two independent renders give σ, as above),
// and the per-pixel error consistent with noise: d = (A - ref)² - (A - B)²/2 averages to the reference's
// own variance, about (A's variance) · spp / (the reference's spp), when nothing differs but noise.
struct SpectralCase {
    const char* name;
    int spp, ref_spp;
};
const SpectralCase kSpectralCases[] = {
    {"cornell-box", 16, 4096},
    {"cornell-box-measured", 16, 2048},
    {"veach-mis", 32, 4096},
    {"coffee", 32, 2048},
    // pbrt-v4 rendered it with BDPT; illum's path tracer converges to the same image.
    {"veach-bidir", 128, 4096},
};
void PrintTo(const SpectralCase& c, std::ostream* os) { *os << c.name; }

class SharedSceneSpectral : public testing::TestWithParam<SpectralCase> {
protected:
    void SetUp() override {
        if (!test::have_shared()) GTEST_SKIP() << "shared dir absent: " << test::shared_dir();
    }
};

TEST_P(SharedSceneSpectral, MatchesPbrtV4) {
    const SpectralCase& c = GetParam();
    Image ref = read_image(test::shared_dir() + "/refs/spectral/" + c.name + ".exr");
    auto t0 = std::chrono::steady_clock::now();
    Image a = render_scene(c.name, c.spp, 1, 0, true), b = render_scene(c.name, c.spp, 2, 0, true);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(a.width(), ref.width());
    ASSERT_EQ(a.height(), ref.height());
    Color3 ma = a.channel_mean(), mb = b.channel_mean(), mr = ref.channel_mean();
    std::printf("%s (spectral): %dx%d, 2 x %d spp in %.1f s\n", c.name, a.width(), a.height(), c.spp, secs);
    for (int ch = 0; ch < 3; ++ch) {
        PixelCheck k = pixel_check(a, b, ref, ch);
        double m = 0.5 * (ma[ch] + mb[ch]);
        double diff = m / mr[ch] - 1, sigma = k.mean_sigma / mr[ch];
        double ref_var = k.mse_noise * c.spp / c.ref_spp;
        std::printf(
            "  channel %d: mean %.6f, pbrt-v4 %.6f, difference %+.2f%% (noise sigma %.2f%%); per-pixel "
            "MSE vs pbrt-v4 / noise = %.3f, d = %.3g +- %.3g (reference variance %.3g)\n",
            ch, m, mr[ch], 100 * diff, 100 * sigma, k.mse_ref / k.mse_noise, k.d_mean, k.d_se, ref_var);
        EXPECT_LT(std::abs(diff), 0.01 + 4.5 * sigma) << c.name << " channel " << ch;
        EXPECT_LT(k.d_mean, ref_var + 4.5 * k.d_se) << c.name << " channel " << ch;
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, SharedSceneSpectral, testing::ValuesIn(kSpectralCases),
                         [](const testing::TestParamInfo<SpectralCase>& i) {
                             std::string n = i.param.name;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

// The Cornell box file against the converged RGB reference (Tungsten, 1024x1024): rendered at the
// reference's resolution, channel means within 1% + 4.5 σ and per-pixel error consistent with noise.
TEST(SharedSceneRgb, CornellBoxMatchesTheRgbReferenceWithinNoise) {
    if (!test::have_shared()) GTEST_SKIP() << "shared dir absent: " << test::shared_dir();
    Image ref = read_image(test::shared_dir() + "/refs/rgb/cornell-box.exr");
    Image a = render_scene("cornell-box", 4, 11, ref.width()),
          b = render_scene("cornell-box", 4, 12, ref.width());
    ASSERT_EQ(a.width(), ref.width());
    ASSERT_EQ(a.height(), ref.height());
    Color3 ma = a.channel_mean(), mr = ref.channel_mean();
    for (int ch = 0; ch < 3; ++ch) {
        PixelCheck k = pixel_check(a, b, ref, ch);
        double diff = ma[ch] / mr[ch] - 1, sigma = std::sqrt(k.mse_noise / a.pixel_count()) / mr[ch];
        std::printf(
            "cornell-box vs RGB reference, channel %d: mean %.6f, reference %.6f, %+.3f%% (sigma %.3f%%); "
            "MSE/noise %.4f, d = %.3g +- %.3g\n",
            ch, ma[ch], mr[ch], 100 * diff, 100 * sigma, k.mse_ref / k.mse_noise, k.d_mean, k.d_se);
        EXPECT_LT(std::abs(diff), 0.01 + 4.5 * sigma) << "channel " << ch;
        EXPECT_LT(std::abs(k.d_mean), 4.5 * k.d_se) << "channel " << ch;
    }
}

// Every scene folder also parses and builds with its full-size scene file, and reports its warnings.
TEST(SharedSceneFiles, EverySceneBuilds) {
    if (!test::have_shared()) GTEST_SKIP() << "shared dir absent: " << test::shared_dir();
    int n = 0;
    for (const auto& dir : std::filesystem::directory_iterator(test::shared_dir() + "/scenes")) {
        if (!dir.is_directory()) continue;
        for (const char* f : {"test.pbrt", "scene-v4.pbrt", "scene.pbrt"}) {
            auto path = dir.path() / f;
            if (!std::filesystem::exists(path)) continue;
            SceneDesc desc = parse_pbrt_file(path.string());
            auto scene = build_scene(desc);
            EXPECT_GT(scene->accelerator.geometry_count(), 0u) << path;
            EXPECT_FALSE(scene->lights.empty()) << path;
            for (const auto& w : scene->warnings) std::printf("%s: warning: %s\n", path.c_str(), w.c_str());
            ++n;
        }
    }
    EXPECT_GE(n, 8);
}

} // namespace
} // namespace illum
