// pbrt-v4's "curve" shape and "hair" material through the whole renderer: a curve's silhouette in an
// orthographic view covers its analytic area, lossless hair under a uniform sky is a white furnace (every
// pixel 1 at unbounded depth), and the material's parameters and h = -1 + 2v as pbrt-v4 reads them.
#include <gtest/gtest.h>

#include "illum/bsdf/hair.h"
#include "test_support.h"

namespace illum {
namespace {

std::unique_ptr<Scene> build(const std::string& text) {
    return build_scene(parse_pbrt_string(text, "<test>", "."));
}

const char* kView = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-1 1 -1 1]
Film "rgb" "integer xresolution" [64] "integer yresolution" [64]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
)";

// A scene of black curves in kView before a white sky builds without warnings, and its image mean is
// 1 - area / 4 (the window is 2 x 2), within 4.5 of the pixels' standard errors.
void expect_covered_area(const std::string& scene, double area, const std::string& what) {
    auto scene_built = build(scene);
    EXPECT_TRUE(scene_built->warnings.empty()) << scene_built->warnings.front();
    test::RenderSetup s;
    s.spp = 16;
    auto r = test::render_pbrt(scene, s);
    test::MeanEstimate m = test::pixel_mean(r.image, 1);
    EXPECT_NEAR(m.mean, 1 - area / 4, 4.5 * m.standard_error + 1e-4) << what;
}

// A black flat curve of length 1.6 and width 0.2 (then widths 0.1 → 0.3) in front of a white sky: the image
// mean is 1 - covered area / 4 (the window is 2 x 2), within the pixels' standard error.
TEST(CurveScene, SilhouetteCoversTheCurvesArea) {
    for (const char* widths : {"\"float width\" [0.2]", "\"float width0\" [0.1] \"float width1\" [0.3]"}) {
        std::string scene = std::string(kView) + R"(
Integrator "path" "integer maxdepth" [1]
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "diffuse" "rgb reflectance" [0 0 0]
Shape "curve" "point3 P" [-0.8 0.1 0  -0.3 0.1 0  0.3 0.1 0  0.8 0.1 0] )" +
                            widths + "\n";
        expect_covered_area(scene, 1.6 * 0.2, widths);
    }
}

// A curve's "alpha" (float or texture) cuts it as pbrt-v4's alpha test does: 0 removes it; a checkerboard
// 0 for u < 1/2 (uscale 2) removes the half of the curve before its middle (x < 0 by the control points'
// symmetry), leaving area 0.8 x 0.2.
TEST(CurveScene, AlphaCutsTheSilhouette) {
    const std::string curve = R"(Shape "curve" "point3 P" [-0.8 0.1 0  -0.3 0.1 0  0.3 0.1 0  0.8 0.1 0]
  "float width" [0.2] )";
    struct Case {
        std::string texture, alpha;
        double area;
    };
    const Case cases[] = {
        {"", R"("float alpha" [0])", 0},
        {R"(Texture "half" "float" "checkerboard" "float uscale" [2] "float vscale" [1]
  "float tex1" [0] "float tex2" [1])",
         R"("texture alpha" "half")", 0.8 * 0.2},
    };
    for (const Case& c : cases) {
        std::string scene = std::string(kView) + R"(
Integrator "path" "integer maxdepth" [1]
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "diffuse" "rgb reflectance" [0 0 0]
)" + c.texture + "\n" + curve +
                            c.alpha + "\n";
        expect_covered_area(scene, c.area, c.alpha);
    }
}

// Lossless fibres (σ_a = 0) scatter all the light they receive: under a uniform sky of radiance 1, at
// unbounded depth, a tuft of them is invisible, every pixel 1. Roughnesses and orientations vary across
// the tuft, so the furnace checks the curve frame, h and the BSDF together.
TEST(CurveScene, LosslessHairIsAWhiteFurnace) {
    std::string scene = std::string(kView) + R"(
Integrator "path" "integer maxdepth" [200]
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
)";
    PCG32 rng(3);
    for (int i = 0; i < 60; ++i) {
        auto u = [&] { return rng.uniform_float(); };
        scene += fmt::format(
            "Material \"hair\" \"rgb sigma_a\" [0 0 0] \"float beta_m\" [{}] \"float beta_n\" [{}]\n",
            0.1 + 0.8 * u(), 0.1 + 0.8 * u());
        float x = -0.8f + 1.6f * u(), y = -0.8f + 1.6f * u(), z = -0.3f + 0.6f * u();
        scene +=
            fmt::format("Shape \"curve\" \"string type\" \"cylinder\" \"float width\" [0.06] \"point3 P\" "
                        "[{} {} {} {} {} {} {} {} {} {} {} {}]\n",
                        x, y, z, x + 0.3f * u(), y + 0.3f, z + 0.2f * u(), x - 0.2f * u(), y + 0.6f,
                        z - 0.2f * u(), x + 0.1f, y + 0.9f * u(), z);
    }
    auto built = build(scene);
    EXPECT_TRUE(built->warnings.empty()) << built->warnings.front();
    test::RenderSetup s;
    s.spp = 16;
    auto r = test::render_pbrt(scene, s);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    for (int c = 0; c < 3; ++c) {
        test::MeanEstimate m = test::pixel_mean(r.image, c);
        EXPECT_NEAR(m.mean, 1, 4.5 * m.standard_error + 3e-3) << "channel " << c;
    }
}

// The material reads h = -1 + 2v from the hit and its absorption from sigma_a, reflectance or the melanins
// (the first given wins; the others are reported unused).
TEST(HairMaterial, ReadsPbrtParametersAndTakesHFromV) {
    auto s = build(R"(WorldBegin
Material "hair" "float eumelanin" [0.8] "float pheomelanin" [0.3] "float eta" [1.6]
    "float beta_m" [0.25] "float beta_n" [0.4] "float alpha" [3]
Shape "sphere"
Material "hair" "rgb reflectance" [0.7 0.4 0.2]
Shape "sphere"
Material "hair" "spectrum sigma_a" [400 0.5 700 1.5]
Shape "sphere"
Material "hair"
Shape "sphere"
)");
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    SurfaceHit hit;
    hit.n = hit.ns = Normal3f(0, 0, 1);
    hit.dpdu = {1, 0, 0};
    hit.uv = {0.3f, 0.8f};
    ScratchArena arena;
    SampledWavelengths lambda = SampledWavelengths::rgb_mode();
    BSDF b = s->materials.front()->bsdf(hit, lambda, arena);
    HairBxDF expect(-1 + 2 * 0.8f, 1.6f, SampledSpectrum(HairBxDF::sigma_a_from_concentration(0.8f, 0.3f)),
                    0.25f, 0.4f, 3);
    const Vector3f wo = normalize(Vector3f(0.3f, 0.2f, 0.9f)), wi = normalize(Vector3f(-0.4f, -0.5f, 0.3f));
    Bsdf3 got = b.f(wo, wi), want = expect.f(wo, wi, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f * want[c]) << c;
    // A later absorption parameter is not read: pbrt-v4 ignores it with a warning.
    auto both = build("WorldBegin\nMaterial \"hair\" \"rgb sigma_a\" [1 1 1] \"rgb reflectance\" [0.5 0.5 "
                      "0.5]\nShape \"sphere\"\n");
    ASSERT_EQ(both->warnings.size(), 1u);
    EXPECT_NE(both->warnings.front().find("reflectance"), std::string::npos) << both->warnings.front();
}

// Curves in object instances, B-spline curves and ribbons build and render without warnings.
TEST(CurveScene, EveryBasisTypeAndInstancesRender) {
    std::string scene = std::string(kView) + R"(
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
ObjectBegin "tuft"
Material "hair" "float eumelanin" [2]
Shape "curve" "string basis" "bspline" "point3 P" [0 0 0 0.2 0.3 0 0.1 0.6 0.1 0.3 0.9 0 0.2 1 0] "float width" [0.05]
Shape "curve" "integer degree" [2] "point3 P" [0.5 0 0 0.6 0.5 0 0.5 1 0] "float width" [0.05]
Shape "curve" "string type" "ribbon" "normal N" [0 0 1 0 0.3 1] "point3 P" [-0.5 0 0 -0.5 0.3 0 -0.4 0.6 0 -0.5 1 0] "float width" [0.1]
ObjectEnd
ObjectInstance "tuft"
Translate -0.6 -0.8 0
ObjectInstance "tuft"
)";
    auto built = build(scene);
    EXPECT_TRUE(built->warnings.empty()) << built->warnings.front();
    test::RenderSetup s;
    s.spp = 4;
    auto r = test::render_pbrt(scene, s);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    test::MeanEstimate m = test::pixel_mean(r.image, 1);
    EXPECT_LT(m.mean, 0.99); // the dark hair shows
}

} // namespace
} // namespace illum
