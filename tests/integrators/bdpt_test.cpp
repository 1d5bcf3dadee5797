// Bidirectional path tracing against closed forms and against the unidirectional integrators. Tolerances
// are 4.5 standard errors measured over the pixels at a fixed seed plus a float allowance (volpath_test.cpp's
// convention); comparisons of two renders use the per-pixel differences, whose spread is the two renders'
// noise alone.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

using test::pixel_mean;
using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5;

RenderSetup bdpt(int spp, int max_depth = -2, bool spectral = false) {
    return test::independent_setup("bdpt", spp, spectral, max_depth);
}

void expect_channels(const RenderResult& r, const double expected[3], const std::string& what,
                     double rel_float = 2e-4) {
    for (int c = 0; c < 3; ++c) {
        auto m = pixel_mean(r.image, c);
        std::printf("%-40s ch %d expected %.6g measured %.6g +- %.2g\n", what.c_str(), c, expected[c], m.mean,
                    m.standard_error);
        EXPECT_NEAR(m.mean, expected[c], kSigmas * m.standard_error + rel_float * expected[c])
            << what << " channel " << c;
    }
    EXPECT_EQ(r.nonfinite_samples, 0u) << what;
}

// The mean over the pixels of a - b per channel, within kSigmas of its standard error (from the
// differences' spread: both renders' noise, the image's own structure cancels).
void expect_agree(const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.pixel_count(), b.pixel_count());
    const std::size_t n = a.pixel_count();
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, mean_a = 0;
        for (std::size_t i = 0; i < n; ++i) {
            double d = double(a.data()[i][c]) - b.data()[i][c];
            sum += d;
            sum2 += d * d;
            mean_a += a.data()[i][c];
        }
        double mean = sum / n, var = std::max(0.0, (sum2 - n * mean * mean) / (n - 1));
        double se = std::sqrt(var / n);
        std::printf("%-40s ch %d mean %.6g difference %.3g +- %.2g\n", what.c_str(), c, mean_a / n, mean, se);
        EXPECT_NEAR(mean, 0.0, kSigmas * se + 1e-4 * mean_a / n) << what << " channel " << c;
    }
}

// Closed furnace (box filter) truncated at maxdepth D: every pixel sees Le Σ_{k<=D} ρ^k.
TEST(BDPT, ClosedFurnace) {
    const double rho = 0.7, le = 0.5;
    const int depth = 8;
    // A box filter: with a wider one the border pixels of the light-tracing strategy (t = 1) miss the splats
    // that would land outside the film, a deficit of ~1e-3 here (pbrt-v4's splats behave alike).
    std::string scene = test::closed_furnace(rho, le, 16);
    scene.insert(scene.find("WorldBegin"), "PixelFilter \"box\"\n");
    RenderResult r = render_pbrt(scene, bdpt(8, depth));
    double e = le * (1 - std::pow(rho, depth + 1)) / (1 - rho);
    const double expected[3] = {e, e, e};
    expect_channels(r, expected, "closed furnace, depth 8");
}

std::string slab_scene(const std::string& medium, double d, const std::string& light) {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [20]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
PixelFilter "box"
Integrator "bdpt" "integer maxdepth" [-1]
WorldBegin
{}
{}
Material "interface"
AttributeBegin
  MediumInterface "slab" ""
  Shape "trianglemesh" "point3 P" [-50 -50 0  50 -50 0  50 50 0  -50 50 0] "integer indices" [0 1 2 0 2 3]
    "normal N" [0 0 1  0 0 1  0 0 1  0 0 1]
  Shape "trianglemesh" "point3 P" [-50 -50 {d}  50 -50 {d}  50 50 {d}  -50 50 {d}]
    "integer indices" [0 1 2 0 2 3] "normal N" [0 0 -1  0 0 -1  0 0 -1  0 0 -1]
AttributeEnd
)",
                       medium, light, fmt::arg("d", -d));
}

// σ_s = 0: exp(-σ_a d) of the environment behind the slab (chromatic σ_a).
TEST(BDPT, AbsorbingSlabTransmittance) {
    const double d = 0.8, sa[3] = {0.5, 1.5, 3.0}, env = 0.6;
    std::string scene =
        slab_scene(fmt::format(R"(MakeNamedMedium "slab" "string type" "homogeneous" "rgb sigma_a" [{} {} {}]
                       "rgb sigma_s" [0 0 0])",
                               sa[0], sa[1], sa[2]),
                   d, fmt::format(R"(LightSource "infinite" "rgb L" [{0} {0} {0}])", env));
    double expected[3];
    for (int c = 0; c < 3; ++c) expected[c] = env * std::exp(-sa[c] * d);
    expect_channels(render_pbrt(scene, bdpt(32)), expected, "absorbing slab");
}

// A sphere of non-absorbing, chromatic, forward-scattering medium in a uniform environment returns the
// environment's radiance (to the truncation at depth 32, below 1e-6 here).
TEST(BDPT, WhiteFurnaceSphere) {
    for (bool spectral : {false, true}) {
        std::string scene = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [18]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "independent"
PixelFilter "box"
Integrator "bdpt" "integer maxdepth" [-1]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [0 0 0] "rgb sigma_s" [0.5 1 2] "float g" [0.5]
AttributeBegin
  MediumInterface "fog" ""
  Material "interface"
  Shape "sphere" "float radius" [1]
AttributeEnd
)";
        const double expected[3] = {0.5, 0.5, 0.5};
        expect_channels(render_pbrt(scene, bdpt(16, -2, spectral)), expected,
                        spectral ? "white furnace, spectral" : "white furnace, RGB", spectral ? 4e-3 : 2e-4);
    }
}

// A small area light over a diffuse floor with a diffuse box and a glass sphere (caustics, light seen
// directly and through the glass).
const char* kSurfaceScene = R"(
LookAt 0 -4 2.5  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
Sampler "independent"
Integrator "path" "integer maxdepth" [5]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [8 6 4]
  Translate 0.3 0.2 2.5
  ReverseOrientation
  Shape "disk" "float radius" [0.4]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
Material "diffuse" "rgb reflectance" [0.2 0.5 0.8]
Shape "trianglemesh" "point3 P" [-1.2 0.2 0  -0.6 0.2 0  -0.6 0.8 0  -1.2 0.8 0  -1.2 0.2 0.8  -0.6 0.2 0.8  -0.6 0.8 0.8  -1.2 0.8 0.8]
  "integer indices" [0 1 5 0 5 4  1 2 6 1 6 5  2 3 7 2 7 6  3 0 4 3 4 7  4 5 6 4 6 7]
Material "dielectric" "float eta" [1.5]
AttributeBegin
  Translate 0.4 -0.2 0.5
  Shape "sphere" "float radius" [0.5]
AttributeEnd
)";

// bdpt at `spp` against `reference` at ref_spp (independent sampler, seed 3), pixel by pixel (expect_agree).
void expect_agrees_with_reference(const std::string& scene, const char* reference, int ref_spp, int spp,
                                  const std::string& what) {
    RenderSetup p;
    p.integrator = reference;
    p.spp = ref_spp;
    p.sampler = "independent";
    p.seed = 3;
    Image ref = render_pbrt(scene, p).image;
    RenderResult r = render_pbrt(scene, bdpt(spp));
    EXPECT_EQ(r.nonfinite_samples, 0u);
    expect_agree(r.image, ref, what);
}

TEST(BDPT, AgreesWithPathOnSurfaces) {
    expect_agrees_with_reference(kSurfaceScene, "path", 256, 64, "surfaces: bdpt - path");
}

// A box of homogeneous scattering medium (chromatic) on the floor, lit by a small area light.
const std::string kMediumScene = test::box_on_floor_scene(test::kMediumBox);

TEST(BDPT, AgreesWithVolPathInMedium) {
    expect_agrees_with_reference(kMediumScene, "volpath", 128, 32, "medium: bdpt - volpath");
}

// The same box as a denser subsurface material's interior, in a scene without named media: connections
// between vertices inside it (or from its boundary into it) cross the interior medium, not vacuum (a
// shortcut that took the scene's named media for all of them made bdpt 15% too bright here: 5 sigma).
const std::string kSubsurfaceScene = test::box_on_floor_scene(R"(AttributeBegin
  Material "subsurface" "rgb sigma_a" [0.1 0.2 0.3] "rgb sigma_s" [3 4 5] "float g" [0.3] "float eta" [1.33]
)");

TEST(BDPT, AgreesWithVolPathInSubsurfaceInterior) {
    expect_agrees_with_reference(kSubsurfaceScene, "volpath", 512, 128, "subsurface: bdpt - volpath");
}

// Same image at any thread count (t = 1 splats are added in chunk order).
TEST(BDPT, DeterministicAcrossThreads) {
    RenderSetup a = bdpt(2), b = bdpt(2);
    a.threads = 1;
    b.threads = 2;
    Image ia = render_pbrt(kMediumScene, a).image, ib = render_pbrt(kMediumScene, b).image;
    ASSERT_EQ(ia.pixel_count(), ib.pixel_count());
    for (std::size_t i = 0; i < ia.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(ia.data()[i][c], ib.data()[i][c]) << "pixel " << i;
}

} // namespace
} // namespace illum

// pbrt-v4's visualizestrategies / visualizeweights: one image per strategy (s, t), named as pbrt-v4 names
// them. The MIS-weighted images add up to the render; the unweighted ones of one depth each estimate the
// same light (transport of that many bounces), so their difference averages to zero within its noise.
namespace illum {
namespace {

using test::render_pbrt;
using test::RenderSetup;

std::string visualize_scene(const char* flag) {
    return std::string("Integrator \"bdpt\" \"integer maxdepth\" [2] \"bool ") + flag + R"(" [true]
LookAt 0 -4 1.5  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [48] "integer yresolution" [32]
PixelFilter "box"
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4]
  Shape "trianglemesh" "point3 P" [-0.5 -0.5 2.5 0.5 -0.5 2.5 0.5 0.5 2.5 -0.5 0.5 2.5] "integer indices" [0 2 1 0 3 2]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
Shape "sphere" "float radius" [0.5]
)";
}

const Image& named(const RenderResult& r, const std::string& name) {
    for (const auto& e : r.extra_images)
        if (e.name == name) return e.image;
    ADD_FAILURE() << "no image " << name;
    return r.image;
}

TEST(BdptVisualize, WeightedStrategiesAddUpToTheRender) {
    RenderSetup setup;
    setup.integrator = "bdpt";
    setup.spp = 16;
    RenderResult r = render_pbrt(visualize_scene("visualizeweights"), setup);
    std::vector<std::string> names;
    for (const auto& e : r.extra_images) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"bdpt_d00_s00_t02.exr", "bdpt_d01_s00_t03.exr",
                                               "bdpt_d01_s01_t02.exr", "bdpt_d01_s02_t01.exr",
                                               "bdpt_d02_s00_t04.exr", "bdpt_d02_s01_t03.exr",
                                               "bdpt_d02_s02_t02.exr", "bdpt_d02_s03_t01.exr"}));
    double worst = 0;
    for (std::size_t i = 0; i < r.image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            double sum = 0;
            for (const auto& e : r.extra_images) sum += e.image.data()[i][c];
            double v = r.image.data()[i][c];
            worst = std::max(worst, std::abs(sum - v) / std::max(1e-3, std::abs(v)));
        }
    EXPECT_LT(worst, 1e-4);
    EXPECT_GT(r.image.channel_mean()[0], 0.01f);
}

TEST(BdptVisualize, UnweightedStrategiesOfOneDepthAgree) {
    RenderSetup setup;
    setup.integrator = "bdpt";
    setup.spp = 64;
    RenderResult r = render_pbrt(visualize_scene("visualizestrategies"), setup);
    // Depth 1 (one bounce on the diffuse floor or sphere): the camera path finds the light (s = 0), next
    // event estimation (s = 1) and light tracing (s = 2, t = 1).
    const Image& a = named(r, "bdpt_d01_s00_t03.exr");
    for (const char* other : {"bdpt_d01_s01_t02.exr", "bdpt_d01_s02_t01.exr"}) {
        const Image& b = named(r, other);
        for (int c = 0; c < 3; ++c) {
            // z of the mean per-pixel difference: pixels are independent estimates of the same values.
            double n = double(a.pixel_count()), sum = 0, sum2 = 0;
            for (std::size_t i = 0; i < a.pixel_count(); ++i) {
                double d = double(a.data()[i][c]) - b.data()[i][c];
                sum += d;
                sum2 += d * d;
            }
            double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
            EXPECT_LT(std::abs(mean), 4 * se) << other << " channel " << c;
            EXPECT_GT(b.channel_mean()[c], 0.01f) << other;
        }
    }
}

} // namespace
} // namespace illum
