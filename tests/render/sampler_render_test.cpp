// The samplers in a render: each of pbrt-v4's Sampler directives parses with its parameters and renders
// without the old "replaced by sobol" warning; the Cornell box's channel means with each sampler agree with
// the independent sampler's within their measured standard errors; images do not depend on the thread
// count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "illum/render/integrator.h"
#include "illum/scene/load.h"
#include "test_support.h"

namespace illum {
namespace {

const char* kScene = R"(
LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 8 "integer yresolution" 8
SAMPLER
WorldBegin
LightSource "point" "rgb I" [1 1 1] "point3 from" [0 0 -3]
Material "diffuse"
Shape "sphere" "float radius" 1
)";

std::unique_ptr<Scene> build_with(const std::string& sampler) {
    std::string text = kScene;
    text.replace(text.find("SAMPLER"), 7, sampler);
    return build_scene(parse_pbrt_string(text, "<test>", "."));
}

TEST(SamplerDirective, EveryPbrtSamplerParsesWithoutWarning) {
    struct Case {
        std::string directive, sampler;
        int spp;
    };
    const Case cases[] = {
        {R"(Sampler "zsobol" "integer pixelsamples" 8 "string randomization" "owen" "integer seed" 3)",
         "zsobol", 8},
        {R"(Sampler "paddedsobol" "integer pixelsamples" 4 "string randomization" "permutedigits")",
         "paddedsobol", 4},
        {R"(Sampler "halton" "integer pixelsamples" 9 "string randomization" "none")", "halton", 9},
        {R"(Sampler "pmj02bn" "integer pixelsamples" 16)", "pmj02bn", 16},
        {R"(Sampler "stratified" "integer xsamples" 3 "integer ysamples" 2 "bool jitter" false)",
         "stratified", 6},
        {R"(Sampler "stratified")", "stratified", 16},
        {R"(Sampler "sobol" "integer pixelsamples" 2)", "sobol", 2},
        {R"(Sampler "independent" "integer pixelsamples" 2)", "independent", 2},
        {"", "sobol", 16}, // no Sampler directive: illum's default (docs/scenes.md)
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.directive);
        auto scene = build_with(c.directive);
        EXPECT_TRUE(scene->warnings.empty()) << (scene->warnings.empty() ? "" : scene->warnings[0]);
        EXPECT_EQ(scene->request.sampler, c.sampler);
        EXPECT_EQ(scene->request.spp, c.spp);
        // It renders.
        auto integrator = make_integrator("path", *scene, 3);
        RenderOptions o;
        o.spp = scene->request.spp;
        o.sampler = scene->request.sampler;
        o.sampler_settings = scene->request.sampler_settings;
        o.quiet = true;
        RenderResult r = render(*scene, *integrator, o);
        EXPECT_FALSE(r.image.has_non_finite());
        EXPECT_GT(r.image.data()[4 * 8 + 4].r, 0.0f);
    }
    auto z = build_with(R"(Sampler "zsobol" "string randomization" "owen" "integer seed" 3)");
    EXPECT_EQ(z->request.sampler_settings.randomization, Randomization::owen);
    EXPECT_EQ(z->request.sampler_seed, 3u);
    auto s =
        build_with(R"(Sampler "stratified" "integer xsamples" 3 "integer ysamples" 2 "bool jitter" false)");
    EXPECT_EQ(s->request.sampler_settings.x_samples, 3);
    EXPECT_EQ(s->request.sampler_settings.y_samples, 2);
    EXPECT_FALSE(s->request.sampler_settings.jitter);
}

TEST(SamplerDirective, BadParametersAreErrorsWithTheirPosition) {
    auto expect_error = [](const std::string& directive, const std::string& message) {
        try {
            build_with(directive);
            ADD_FAILURE() << "no error for " << directive;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("<test>:5"), std::string::npos) << e.what();
        }
    };
    expect_error(R"(Sampler "zsobol" "string randomization" "fast")", "unknown randomization \"fast\"");
    expect_error(R"(Sampler "halton" "string randomization" "fastowen")", "no \"fastowen\"");
    expect_error(R"(Sampler "pmj02bn" "integer pixelsamples" 65537)", "at most 65536");
    expect_error(R"(Sampler "stratified" "integer xsamples" 0)", "xsamples and ysamples must be positive");
    expect_error(R"(Sampler "metropolis")", "unknown sampler \"metropolis\"");
}

// The built-in Cornell box (64 x 64, path tracing to depth 5) with sampler `name`.
RenderResult cornell(const std::string& name, int spp, int threads, uint64_t seed = 0) {
    SceneDesc desc = load_scene_desc("");
    desc.set_film_resolution(64, 64);
    auto scene = build_scene(desc);
    auto integrator = make_integrator("path", *scene, 5);
    RenderOptions o;
    o.spp = spp;
    o.sampler = name;
    o.threads = threads;
    o.seed = seed;
    o.quiet = true;
    return render(*scene, *integrator, o);
}

// One channel's image mean from two renders A, B of different seeds: the mean of (A + B)/2 and its
// standard error from the per-pixel noise, var = mean over pixels of (A - B)²/2, as sqrt(var / (2 n)).
// (Pixels' noise is independent for independent, padded and stratified sampling and negatively correlated
// for zsobol's and pmj02bn's blue noise and Halton's one global sequence, so this overstates their error.)
struct NoisyMean {
    double mean = 0, standard_error = 0;
};
NoisyMean noisy_mean(const Image& a, const Image& b, int c) {
    double sum = 0, d2 = 0;
    const size_t n = a.pixel_count();
    for (size_t i = 0; i < n; ++i) {
        const double x = a.data()[i][c], y = b.data()[i][c];
        sum += 0.5 * (x + y);
        d2 += 0.5 * (x - y) * (x - y);
    }
    return {sum / double(n), std::sqrt(d2 / double(n) / (2.0 * double(n)))};
}

TEST(SamplerRender, CornellBoxMeansAgreeWithIndependent) {
    // Reference: independent at 64 spp. Each sampler at 16 spp. Agreement within 5 combined standard
    // errors per channel.
    Image r1 = cornell("independent", 64, 0, 1).image, r2 = cornell("independent", 64, 0, 2).image;
    for (const char* name : {"zsobol", "paddedsobol", "halton", "pmj02bn", "stratified", "sobol"}) {
        RenderResult a = cornell(name, 16, 0, 1), b = cornell(name, 16, 0, 2);
        EXPECT_EQ(a.nonfinite_samples + b.nonfinite_samples, 0u);
        for (int c = 0; c < 3; ++c) {
            NoisyMean m = noisy_mean(a.image, b.image, c), ref = noisy_mean(r1, r2, c);
            const double se = std::hypot(m.standard_error, ref.standard_error);
            std::printf(
                "  %-12s channel %d: mean %.5f (se %.5f), independent %.5f (se %.5f): %.1f se apart\n", name,
                c, m.mean, m.standard_error, ref.mean, ref.standard_error, std::abs(m.mean - ref.mean) / se);
            EXPECT_NEAR(m.mean, ref.mean, 5 * se) << name << " channel " << c;
        }
    }
}

TEST(SamplerRender, ImagesDoNotDependOnTheThreadCount) {
    for (const char* name : {"zsobol", "paddedsobol", "halton", "pmj02bn", "stratified"}) {
        Image one = cornell(name, 4, 1).image, two = cornell(name, 4, 2).image;
        ASSERT_EQ(one.pixel_count(), two.pixel_count());
        size_t differ = 0;
        for (size_t i = 0; i < one.pixel_count(); ++i)
            differ += !(one.data()[i].r == two.data()[i].r && one.data()[i].g == two.data()[i].g &&
                        one.data()[i].b == two.data()[i].b);
        EXPECT_EQ(differ, 0u) << name;
    }
}

} // namespace
} // namespace illum
