// Adaptive sampling (render/adaptive_sampling.h): the schedule on films filled by hand (first rounds, budget,
// threshold, window, bad settings), then renders: the same image at any thread count, the budget kept, lower
// error than uniform sampling for the same samples where the noise is uneven, the expectation unchanged, and
// clear errors where it does not apply; BDPT's splats normalised by the samples taken.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <numeric>

#include "illum/math/rng.h"
#include "illum/render/adaptive_sampling.h"
#include "illum/render/integrator.h"
#include "illum/render/render_group.h"
#include "illum/scene/load.h"
#include "illum/util/error.h"
#include "test_support.h"

namespace illum {
namespace {

// Runs a planned round on `film` as a render would: each pixel's new samples in order, from value(x, y, k).
template <class Value>
void take_round(AdaptiveSchedule& s, Film& film, const PixelBounds& b, Value&& value) {
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x)
            for (int k = s.from(x, y); k < s.to(x, y); ++k) {
                float v = value(x, y, k);
                film.add_sample(x, y, Color3(v, v, v), 1.0f);
            }
    s.commit();
}

// Pixels of a 16 × 16 film whose samples are all 1 (quiet) except those for which noisy(x, y) holds, whose
// samples are 1 ± 1 at random.
struct Noise {
    PCG32 rng;
    std::function<bool(int, int)> noisy;
    float operator()(int x, int y, int) {
        return noisy(x, y) ? (rng.uniform_float() < 0.5f ? 0.0f : 2.0f) : 1.0f;
    }
};

TEST(AdaptiveSchedule, FirstRoundsGiveEveryPixelHalfThenAllOfMinSpp) {
    const PixelBounds b{2, 3, 10, 7};
    Film film(12, 8);
    AdaptiveSchedule s(b, {true, 0, 16});
    EXPECT_EQ(s.plan(film, 1000000), 8u * 32);
    EXPECT_EQ(s.from(2, 3), 0);
    EXPECT_EQ(s.to(9, 6), 8);
    take_round(s, film, b, [](int, int, int) { return 1.0f; });
    EXPECT_EQ(s.plan(film, 1000000), 8u * 32);
    EXPECT_EQ(s.from(5, 5), 8);
    EXPECT_EQ(s.to(5, 5), 16);
    take_round(s, film, b, [](int, int, int) { return 1.0f; });
    EXPECT_EQ(s.taken(), 16u * 32);
    EXPECT_EQ(s.min_taken(), 16u);
    EXPECT_EQ(s.max_taken(), 16u);
    // A budget below the first round's: fewer samples, a power of two.
    AdaptiveSchedule small(b, {true, 0, 16});
    EXPECT_EQ(small.plan(film, 5 * 32), 4u * 32);
}

TEST(AdaptiveSchedule, NoisyPixelsGrowQuietOnesStayAtTheFloorAndTheBudgetHolds) {
    const PixelBounds b{0, 0, 16, 16};
    Film film(16, 16);
    AdaptiveSchedule s(b, {true, 0, 8});
    Noise noise{PCG32(5), [](int x, int) { return x >= 12; }}; // four noisy columns on the right
    const std::uint64_t budget = 64 * 256;
    while (s.plan(film, budget) > 0) take_round(s, film, b, std::ref(noise));
    EXPECT_LE(s.taken(), budget);
    EXPECT_GE(s.taken(), budget / 2);
    // Quiet pixels far from the noise keep the floor (a quarter of the mean, 16); the noisy ones take most.
    EXPECT_EQ(s.from(0, 8), 16);
    EXPECT_GE(s.from(14, 8), 128);
    // Counts stay powers of two (each half a stratified set of the sequence).
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            EXPECT_TRUE(std::has_single_bit(unsigned(s.from(x, y)))) << x << " " << y;
    EXPECT_GT(s.level(), 0);
}

TEST(AdaptiveSchedule, OneNoisyPixelIsNotAloneItsWindowGrowsWithIt) {
    const PixelBounds b{0, 0, 16, 16};
    Film film(16, 16);
    AdaptiveSchedule s(b, {true, 0, 8});
    Noise noise{PCG32(9), [](int x, int y) { return x == 8 && y == 8; }};
    const std::uint64_t budget = 32 * 256;
    while (s.plan(film, budget) > 0) take_round(s, film, b, std::ref(noise));
    // Its 5 × 5 window shares its estimate: the neighbours two pixels away grow too, three away do not.
    EXPECT_GT(s.from(10, 8), s.from(11, 8));
    EXPECT_GT(s.from(8, 6), s.from(8, 5));
    EXPECT_GT(s.from(10, 10), 8);
    EXPECT_EQ(s.from(11, 11), 8);
}

TEST(AdaptiveSchedule, AThresholdStopsTheRenderOnceEveryPixelIsBelowIt) {
    const PixelBounds b{0, 0, 16, 16};
    // Every pixel quiet: after the first two rounds nothing grows, however large the budget.
    {
        Film film(16, 16);
        AdaptiveSchedule s(b, {true, 0.01, 8});
        int rounds = 0;
        while (s.plan(film, 1u << 30) > 0)
            take_round(s, film, b, [](int, int, int) { return 1.0f; }), ++rounds;
        EXPECT_EQ(rounds, 2);
        EXPECT_EQ(s.taken(), 8u * 256);
    }
    // Noisy pixels grow until e = s̃ / (n m̄) is at most the threshold, then the render ends within budget.
    {
        Film film(16, 16);
        const double threshold = 0.002;
        AdaptiveSchedule s(b, {true, threshold, 8});
        Noise noise{PCG32(3), [](int x, int) { return x < 4; }};
        while (s.plan(film, 1u << 30) > 0) take_round(s, film, b, std::ref(noise));
        EXPECT_LT(s.taken(), 1u << 30);
        EXPECT_LE(s.level(), threshold * 1.0000001);
        // The noisy pixels' samples have σ = 1 about a mean of 1 (m̄ = 1): e = 1 / n ≤ 0.002 wants about 500
        // samples, and a pixel doubles while its target is above √2 n, so it stops between 512 / √2 and 1024.
        EXPECT_GE(s.from(0, 5), 256);
        EXPECT_LE(s.from(0, 5), 1024);
        EXPECT_EQ(s.from(12, 5), 8);
    }
}

TEST(AdaptiveSchedule, BadSettingsAreRefused) {
    const PixelBounds b{0, 0, 4, 4};
    EXPECT_THROW(AdaptiveSchedule(b, {true, 0, 3}), Error);
    EXPECT_THROW(AdaptiveSchedule(b, {true, 0, 1}), Error);
    EXPECT_THROW(AdaptiveSchedule(b, {true, -1, 16}), Error);
    EXPECT_THROW(AdaptiveSchedule(b, {true, std::nan(""), 16}), Error);
    EXPECT_THROW(AdaptiveSchedule(PixelBounds{0, 0, 0, 4}, {true, 0, 16}), Error);
}

// A dim diffuse room with a small bright emitter in view: most of the error is at the emitter's edges and
// in its glow, where adaptive sampling puts the samples.
const char* kUnevenScene = R"(
LookAt 0 0 -4  0 0 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 48 "integer yresolution" 48
Sampler "sobol" "integer pixelsamples" 64
Integrator "path" "integer maxdepth" 3
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [40 40 40]
  Translate 0.3 0.2 0
  Shape "sphere" "float radius" 0.12
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "point3 P" [-3 -1 -3  3 -1 -3  3 -1 3  -3 -1 3] "integer indices" [0 1 2 0 2 3]
Shape "trianglemesh" "point3 P" [-3 -3 2  3 -3 2  3 3 2  -3 3 2] "integer indices" [0 1 2 0 2 3]
)";

RenderResult render_uneven(int spp, bool adaptive, int threads, std::uint64_t seed = 1,
                           const std::string& integrator = "path") {
    test::RenderSetup setup;
    setup.integrator = integrator;
    setup.spp = spp;
    setup.threads = threads;
    setup.seed = seed;
    setup.adaptive = adaptive;
    return test::render_pbrt(kUnevenScene, setup);
}

double image_mean(const Image& image) {
    double m = 0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i) m += image.data()[i].average();
    return m / double(image.pixel_count());
}

double sample_variance(const std::vector<double>& v) {
    const double m = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    double s = 0;
    for (double d : v) s += (d - m) * (d - m);
    return s / double(v.size() - 1);
}

// The mean of `diffs` (image means less a reference's, one per seed) is within 4 standard errors of 0: the
// standard error from the diffs' spread and the reference's own error, estimated from the spread of
// `uniform_means` (uniform renders with `times` fewer samples than the reference).
void expect_same_mean(const std::vector<double>& diffs, const std::vector<double>& uniform_means,
                      double times) {
    const double n = double(diffs.size());
    const double mean = std::accumulate(diffs.begin(), diffs.end(), 0.0) / n;
    const double standard_error =
        std::sqrt(sample_variance(diffs) / n + sample_variance(uniform_means) / times);
    EXPECT_LT(std::abs(mean), 4 * standard_error) << mean << " ± " << standard_error;
}

double mse(const Image& a, const Image& b) {
    double s = 0;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            double d = double(a.data()[i][c]) - double(b.data()[i][c]);
            s += d * d;
        }
    return s / double(3 * a.pixel_count());
}

TEST(AdaptiveRender, SameImageAtAnyThreadCountAndTheBudgetHolds) {
    RenderResult one = render_uneven(32, true, 1), two = render_uneven(32, true, 2);
    ASSERT_EQ(one.image.pixel_count(), two.image.pixel_count());
    for (std::size_t i = 0; i < one.image.pixel_count(); ++i)
        ASSERT_EQ(one.image.data()[i], two.image.data()[i]) << i;
    EXPECT_LE(one.samples, 32u * 48 * 48);
    EXPECT_GE(one.samples, 16u * 48 * 48);
    ASSERT_TRUE(one.adaptive.has_value());
    EXPECT_EQ(one.adaptive->min_spp, 16u);
    EXPECT_GT(one.adaptive->max_spp, 64u);
    EXPECT_GE(one.adaptive->rounds, 3);
    EXPECT_EQ(one.spp, int((one.samples + 48 * 48 / 2) / (48 * 48)));
}

// Against a uniform render of 64 times the samples (its own error about 1/64 of theirs, in MSE), the
// adaptive image at 32 spp has less than 0.1 of the uniform image's MSE at 32 spp, for each of four seeds
// (measured 0.014-0.023: nearly all of the uniform image's error is at the light's edges, where the
// samples go). The images' means agree within 4 standard errors of their difference, estimated from the
// four seeds and the reference's own error: adaptive sampling moves samples, not the expectation (measured
// -0.00027 ± 0.00019 of a mean of 0.217).
TEST(AdaptiveRender, LessErrorForTheSameSamplesAndTheSameMean) {
    const Image reference = render_uneven(2048, false, 0, 99).image;
    std::vector<double> diffs, uniform_means;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(seed);
        RenderResult uniform = render_uneven(32, false, 0, seed), adaptive = render_uneven(32, true, 0, seed);
        EXPECT_LE(adaptive.samples, uniform.samples);
        const double ratio = mse(adaptive.image, reference) / mse(uniform.image, reference);
        EXPECT_LT(ratio, 0.1);
        diffs.push_back(image_mean(adaptive.image) - image_mean(reference));
        uniform_means.push_back(image_mean(uniform.image));
    }
    expect_same_mean(diffs, uniform_means, 64);
}

// BDPT: the camera strategies' estimates decide where samples go, every sample traces its light subpath, and
// the splats are normalised by the samples taken in all. The same image at 1 and 2 threads; the image mean
// agrees with a uniform BDPT render of 512 spp within 4 standard errors (from the four seeds' spread and the
// reference's own error), also when a threshold ends the render at 16 of its 64 spp, where normalising the
// splats by the spp asked would darken them fourfold.
TEST(AdaptiveRender, BdptKeepsItsSplatsNormalised) {
    RenderResult one = render_uneven(32, true, 1, 1, "bdpt"), two = render_uneven(32, true, 2, 1, "bdpt");
    for (std::size_t i = 0; i < one.image.pixel_count(); ++i)
        ASSERT_EQ(one.image.data()[i], two.image.data()[i]) << i;
    ASSERT_TRUE(one.adaptive.has_value());
    EXPECT_GT(one.adaptive->max_spp, 32u);

    const double reference = image_mean(render_uneven(512, false, 0, 99, "bdpt").image);
    auto check = [&](const std::function<RenderResult(std::uint64_t)>& render_seed) {
        std::vector<double> diffs, uniform;
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            diffs.push_back(image_mean(render_seed(seed).image) - reference);
            uniform.push_back(image_mean(render_uneven(32, false, 0, seed, "bdpt").image));
        }
        expect_same_mean(diffs, uniform, 16);
    };
    check([](std::uint64_t seed) { return render_uneven(32, true, 0, seed, "bdpt"); });
    check([](std::uint64_t seed) {
        auto scene = build_scene(parse_pbrt_string(kUnevenScene, "<test>", "."));
        auto bdpt = make_integrator("bdpt", *scene, 3);
        RenderOptions opt;
        opt.spp = 64;
        opt.seed = seed;
        opt.quiet = true;
        opt.adaptive = {true, 1000.0, 16};
        RenderResult r = render(*scene, *bdpt, opt);
        EXPECT_EQ(r.samples, 16u * 48 * 48);
        return r;
    });
}

TEST(AdaptiveRender, RefusedWhereItDoesNotApply) {
    auto scene = build_scene(parse_pbrt_string(kUnevenScene, "<test>", "."));
    RenderOptions opt;
    opt.spp = 4;
    opt.quiet = true;
    opt.adaptive.enabled = true;
    for (const char* name : {"lightpath", "sppm", "vcm"}) {
        auto integrator = make_integrator(name, *scene, 3);
        EXPECT_THROW(render(*scene, *integrator, opt), Error) << name;
    }
    // BDPT's strategy images are normalised by a number of samples every pixel shares.
    std::string visualize = kUnevenScene;
    visualize.replace(visualize.find("Integrator \"path\""), 17,
                      "Integrator \"bdpt\" \"bool visualizestrategies\" true");
    auto visualizing = build_scene(parse_pbrt_string(visualize, "<test>", "."));
    auto bdpt = make_integrator("bdpt", *visualizing, 3);
    EXPECT_THROW(render(*visualizing, *bdpt, opt), Error);
    auto path = make_integrator("path", *scene, 3);
    SoloShare share(0, 2);
    opt.group = &share;
    EXPECT_THROW(render(*scene, *path, opt), Error);
    opt.group = nullptr;
    opt.adaptive.min_spp = 12;
    EXPECT_THROW(render(*scene, *path, opt), Error);
}

} // namespace
} // namespace illum
