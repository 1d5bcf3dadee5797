// pbrt-v4's analytic shapes through the parser, builder and renderer: every parameter of sphere, disk and
// cylinder is read without warnings; bad values are errors at their position; partial emitters give the
// closed-form irradiance; alpha cut-outs on them behave as on meshes (a hit is kept with probability
// alpha, independently at each surface a ray crosses, for camera and shadow rays alike).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "illum/light/diffuse_area_light.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

std::unique_ptr<Scene> build(const std::string& world) {
    std::string text =
        "Camera \"perspective\"\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "WorldBegin\n" +
        world;
    return build_scene(parse_pbrt_string(text, "<test>", "."));
}

TEST(AnalyticShapesScene, EveryParameterIsRead) {
    auto s = build(R"(
Texture "holes" "float" "checkerboard" "float tex1" [0] "float tex2" [1]
Shape "sphere" "float radius" [2] "float zmin" [-1] "float zmax" [1.5] "float phimax" [270] "float alpha" [0.5]
Shape "disk" "float radius" [2] "float innerradius" [0.5] "float height" [1] "float phimax" [90] "texture alpha" "holes"
Shape "cylinder" "float radius" [2] "float zmin" [-1] "float zmax" [1.5] "float phimax" [180] "float alpha" [0.25]
Scale 1 2 3
Shape "sphere"
)");
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_EQ(s->accelerator.geometry_count(), 4u);
    EXPECT_EQ(s->accelerator.triangle_count(), 0u) << "the cylinder is analytic, not tessellated";
}

TEST(AnalyticShapesScene, BadParametersAreErrorsAtTheirPosition) {
    using test::expect_error;
    expect_error([] { build("Shape \"sphere\" \"float radius\" [-1]\n"); },
                 "<test>:4:", "radius must be positive");
    expect_error([] { build("Shape \"sphere\"\n  \"float phimax\" [400]\n"); },
                 "<test>:5:", "phimax must be in (0, 360]");
    expect_error([] { build("Shape \"sphere\" \"float zmin\" [2] \"float zmax\" [3]\n"); },
                 "<test>:4:", "leave nothing of the sphere");
    expect_error([] { build("Shape \"disk\" \"float phimax\" [0]\n"); },
                 "<test>:4:", "phimax must be in (0, 360]");
    expect_error([] { build("Shape \"disk\" \"float innerradius\" [2]\n"); },
                 "<test>:4:", "innerradius < radius");
    expect_error([] { build("Shape \"cylinder\" \"float zmin\" [1] \"float zmax\" [1]\n"); },
                 "<test>:4:", "zmin != zmax");
    expect_error([] { build("Shape \"cylinder\" \"float phimax\" [-5]\n"); }, "<test>:4:", "phimax");
}

// pbrt-v4's "power" sets L = P / (π A) with the exact area of the partial shape.
TEST(AnalyticShapesScene, PowerUsesThePartialArea) {
    auto s = build(
        "AttributeBegin\nAreaLightSource \"diffuse\" \"float power\" [10]\n"
        "Shape \"sphere\" \"float radius\" [2] \"float zmin\" [-1] \"float zmax\" [0.5] \"float phimax\" "
        "[90]\nAttributeEnd\n");
    ASSERT_EQ(s->lights.size(), 1u);
    auto* light = dynamic_cast<const DiffuseAreaLight*>(s->lights.front().get());
    ASSERT_NE(light, nullptr);
    double area = kPiD / 2 * 2 * 1.5; // φmax r (zmax - zmin)
    EXPECT_NEAR(light->shape()->area(), area, 1e-5 * area);
    Radiance3 l = light->emitted({1, 0, 0}, {1, 0, 0}, SampledWavelengths::rgb_mode());
    EXPECT_NEAR(l.rgb().g, 10 / (kPiD * area), 1e-5);
    EXPECT_NEAR(light->power().rgb().g, 10, 1e-4);
}

// E/π at the origin of the white receiver (z = 0, normal +z) for the emitter `world`, rendered with the
// direct integrator (light and BSDF sampling with MIS).
test::MeanEstimate irradiance_over_pi(const std::string& world) {
    test::RenderSetup s;
    s.integrator = "direct";
    s.spp = 64;
    auto r = test::render_pbrt(test::irradiance_receiver(world), s);
    return test::pixel_mean(r.image, 1);
}

void expect_irradiance(const std::string& world, double expected, const char* what) {
    auto m = irradiance_over_pi(world);
    ::testing::Test::RecordProperty(
        what, fmt::format("{:.6g} +- {:.2g} (closed form {:.6g})", m.mean, m.standard_error, expected));
    EXPECT_NEAR(m.mean, expected, 4.5 * m.standard_error + 1e-4 * expected)
        << what << ": SE " << m.standard_error << ", relative error " << (m.mean / expected - 1);
    EXPECT_GT(m.standard_error, 0) << what;
}

TEST(AnalyticShapesRender, PartialEmittersGiveClosedFormIrradiance) {
    // The half (φ <= 180°) of a sphere R = 0.5 at distance d = 2 above: half a whole sphere's E/π = L R²/d²
    // by symmetry (the cut plane holds the receiver), seen from outside and sampled by area.
    expect_irradiance(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 1 1]
Translate 0 0 2
Shape "sphere" "float radius" [0.5] "float phimax" [180]
AttributeEnd)",
                      0.5 * 0.25 / 4, "half sphere");
    // A cap z >= 1 of the sphere R = 2 about the receiver, emitting inwards: E/π = L sin²θc, cos θc = 1/2.
    expect_irradiance(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 1 1]
ReverseOrientation
Shape "sphere" "float radius" [2] "float zmin" [1]
AttributeEnd)",
                      0.75, "spherical cap from its centre");
    // A half disk R = 1 at h = 1 facing down: half of π L R²/(R² + h²), over π.
    expect_irradiance(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [2 2 2]
Translate 0 0 1
ReverseOrientation
Shape "disk" "float radius" [1] "float phimax" [180]
AttributeEnd)",
                      2 * 0.25, "half disk");
    // The inside of a cylinder R = 1 around the receiver's normal from h1 = 0.5 to h2 = 2: the band of
    // polar angles between atan(R/h2) and atan(R/h1) gives E/π = L (R²/(R² + h1²) - R²/(R² + h2²)).
    expect_irradiance(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 1 1]
ReverseOrientation
Shape "cylinder" "float radius" [1] "float zmin" [0.5] "float zmax" [2]
AttributeEnd)",
                      0.8 - 0.2, "cylinder band");
    // The same band under a non-uniform scale (z x 2): exact area and pdf without a similarity.
    expect_irradiance(R"(AttributeBegin
AreaLightSource "diffuse" "rgb L" [1 1 1]
ReverseOrientation
Scale 1 1 2
Shape "cylinder" "float radius" [1] "float zmin" [0.25] "float zmax" [1]
AttributeEnd)",
                      0.8 - 0.2, "scaled cylinder band");
}

// An emitter of radiance 1 at z = 0 seen from above through a black occluder.
std::string through_occluder(const std::string& occluder, int resolution = 16) {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-1 1 -1 1]
Film "rgb" "integer xresolution" [{}] "integer yresolution" [{}]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
WorldBegin
Texture "holes" "float" "checkerboard" "float tex1" [0] "float tex2" [1] "float uscale" [4] "float vscale" [2]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Material "diffuse" "rgb reflectance" [0 0 0]
  Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
AttributeEnd
Material "diffuse" "rgb reflectance" [0 0 0]
{}
)",
                       resolution, resolution, occluder);
}

TEST(AnalyticShapesAlpha, ConstantAlphaIsTestedAtEachCrossing) {
    test::RenderSetup s;
    s.spp = 64;
    // A bowl (the lower half of a sphere R = 2 whose centre is at z = 2.5): each ray crosses it once.
    auto bowl = test::pixel_mean(test::render_pbrt(through_occluder(R"(Translate 0 0 2.5
Shape "sphere" "float radius" [2] "float zmax" [0] "float alpha" [0.5])"),
                                                   s)
                                     .image,
                                 1);
    ::testing::Test::RecordProperty("bowl", fmt::format("{:.5g} +- {:.2g}", bowl.mean, bowl.standard_error));
    EXPECT_NEAR(bowl.mean, 0.5, 4.5 * bowl.standard_error) << "SE " << bowl.standard_error;
    // The whole sphere: two crossings, each passed with probability 1/2 (pbrt-v4 continues the ray past
    // a rejected hit, with a new random number).
    auto ball = test::pixel_mean(test::render_pbrt(through_occluder(R"(Translate 0 0 2.5
Shape "sphere" "float radius" [2] "float alpha" [0.5])"),
                                                   s)
                                     .image,
                                 1);
    ::testing::Test::RecordProperty("ball", fmt::format("{:.5g} +- {:.2g}", ball.mean, ball.standard_error));
    EXPECT_NEAR(ball.mean, 0.25, 4.5 * ball.standard_error) << "SE " << ball.standard_error;
}

// Shadow rays: the receiver lit by a disk light through a disk of alpha 0.5 gets half the light.
TEST(AnalyticShapesAlpha, ShadowRaysPassThroughCutOuts) {
    auto scene = [](const std::string& alpha) {
        return test::disk_light_through("Translate 0 0 1\nShape \"disk\" \"float radius\" [3] " + alpha);
    };
    test::RenderSetup s;
    s.integrator = "direct";
    s.spp = 64;
    auto open = test::pixel_mean(test::render_pbrt(scene(R"("float alpha" [0])"), s).image, 1);
    auto cut = test::pixel_mean(test::render_pbrt(scene(R"("float alpha" [0.5])"), s).image, 1);
    ::testing::Test::RecordProperty("shadow", fmt::format("open {:.5g} +- {:.2g}, alpha 0.5 {:.5g} +- {:.2g}",
                                                          open.mean, open.standard_error, cut.mean,
                                                          cut.standard_error));
    EXPECT_NEAR(open.mean, 0.2, 4.5 * open.standard_error + 1e-4); // π L R²/(R² + h²) / π, R = 1, h = 2
    EXPECT_NEAR(cut.mean, 0.5 * open.mean,
                4.5 * std::hypot(cut.standard_error, 0.5 * open.standard_error) + 1e-5);
}

// A checkerboard alpha on a disk (uv = (φ/2π, 1 - ρ), 4 x 2 checks, alpha 0 on the even ones) is a set of
// holes: every pixel shows the emitter behind in proportion to its hole coverage, computed here from the
// uv formula by supersampling.
TEST(AnalyticShapesAlpha, CheckerboardAlphaOnADisk) {
    const int res = 16;
    test::RenderSetup s;
    s.spp = 64;
    auto r = test::render_pbrt(
        through_occluder("Translate 0 0 1\nShape \"disk\" \"texture alpha\" \"holes\"", res), s);
    auto hole = [](double x, double y) {
        double rho = std::hypot(x, y);
        if (rho > 1) return 1.0;
        double phi = std::atan2(y, x);
        if (phi < 0) phi += 2 * kPiD;
        double u = phi / (2 * kPiD), v = 1 - rho;
        return (int(std::floor(4 * u) + std::floor(2 * v)) & 1) == 0 ? 1.0 : 0.0;
    };
    int bad = 0, exact = 0;
    for (int j = 0; j < res; ++j)
        for (int i = 0; i < res; ++i) {
            // pbrt's LookAt down -z with up +y: image right is world -x, image up is world +y.
            double cover = 0;
            constexpr int sub = 16;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double sx = -1 + 2 * (i + (a + 0.5) / sub) / res,
                           sy = 1 - 2 * (j + (b + 0.5) / sub) / res;
                    cover += hole(-sx, sy);
                }
            cover /= sub * sub;
            double v = r.image(i, j).g;
            double tol = 4.5 * std::sqrt(cover * (1 - cover) / s.spp) + 0.02;
            bad += std::abs(v - cover) > tol;
            exact += (cover == 0 && v == 0) || (cover == 1 && v == 1);
        }
    ::testing::Test::RecordProperty("checkerboard", fmt::format("{} of {} pixels exact", exact, res * res));
    EXPECT_EQ(bad, 0);
    EXPECT_GT(exact, res * res / 3) << "pixels wholly inside a check are exactly hole or solid";
}

} // namespace
} // namespace illum
