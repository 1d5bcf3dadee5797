// Alpha cut-outs (pbrt-v4's "alpha" on meshes): a hit is kept with probability alpha, for camera,
// continuation and shadow rays alike, so an occluder of constant alpha a lets through 1 - a of what lies
// behind it, and a 0/1 checkerboard of alpha is a set of holes.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

// An emitter of radiance 1 at z = 0 seen from above through a black occluder at z = 1 with the given alpha.
std::string through_occluder(const std::string& alpha) {
    return fmt::format(R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-1 1 -1 1]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
WorldBegin
{}
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Material "diffuse" "rgb reflectance" [0 0 0]
  Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
AttributeEnd
Material "diffuse" "rgb reflectance" [0 0 0]
Shape "trianglemesh" "point3 P" [-1 -1 1 1 -1 1 1 1 1 -1 1 1] "integer indices" [0 1 2 0 2 3]
    "point2 uv" [0 0 1 0 1 1 0 1] {}
)",
                       alpha.find("Texture") == 0 ? alpha.substr(0, alpha.find('\n')) : "",
                       alpha.find("Texture") == 0 ? alpha.substr(alpha.find('\n') + 1) : alpha);
}

TEST(Alpha, ConstantAlphaLetsThroughOneMinusAlpha) {
    test::RenderSetup s;
    s.spp = 64;
    auto r = test::render_pbrt(through_occluder(R"("float alpha" [0.3])"), s);
    auto m = test::pixel_mean(r.image, 1);
    EXPECT_NEAR(m.mean, 0.7, 4.5 * m.standard_error + 1e-4) << "standard error " << m.standard_error;
    EXPECT_GT(m.standard_error, 0) << "the alpha test is stochastic per ray";
}

TEST(Alpha, CheckerboardAlphaIsHoles) {
    test::RenderSetup s;
    s.spp = 16;
    auto r = test::render_pbrt(through_occluder("Texture \"holes\" \"float\" \"checkerboard\" \"float tex1\" "
                                                "[0] \"float tex2\" [1] \"float uscale\" [4] "
                                                "\"float vscale\" [4]\n\"texture alpha\" \"holes\""),
                               s);
    // 16 pixels across 4 checks: each pixel is wholly hole (radiance 1) or wholly opaque (0).
    int holes = 0, solid = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            float v = r.image(x, y).g;
            holes += v > 0.999f;
            solid += v < 0.001f;
        }
    EXPECT_EQ(holes, 128);
    EXPECT_EQ(solid, 128);
}

// Shadow rays: a white receiver lit by a disk light through an occluder of alpha 0.4 gets 0.6 of the
// unoccluded irradiance.
TEST(Alpha, ShadowRaysPassThroughCutOuts) {
    auto scene = [](const std::string& alpha) {
        return test::disk_light_through("Shape \"trianglemesh\" \"point3 P\" [-3 -3 1 3 -3 1 3 3 1 -3 3 1] "
                                        "\"integer indices\" [0 1 2 0 2 3] " +
                                        alpha);
    };
    test::RenderSetup s;
    s.integrator = "direct";
    s.spp = 64;
    auto open = test::pixel_mean(test::render_pbrt(scene(R"("float alpha" [0])"), s).image, 1);
    auto cut = test::pixel_mean(test::render_pbrt(scene(R"("float alpha" [0.4])"), s).image, 1);
    double expected = 0.6 * open.mean;
    EXPECT_NEAR(cut.mean, expected, 4.5 * std::hypot(cut.standard_error, 0.6 * open.standard_error) + 1e-5);
}

// Emitters with a cut-out do not emit where it removes them (pbrt-v4): an emitting square (mesh) and an
// emitting disk (analytic) over the receiver, half of each cut away by a 0/1 checkerboard laid out so
// that the receiver at the origin sees exactly half of the full irradiance. Both next-event estimation
// (sample_li) and emission found by BSDF sampling (radiance) are masked: the path integrator's MIS
// combines them, and the direct integrator's too.
TEST(Alpha, CutOutEmittersDoNotEmitWhereCut) {
    auto scene = [](const std::string& shape, const std::string& alpha) {
        return test::irradiance_receiver(fmt::format(R"(
Texture "checks" "float" "checkerboard" "float uscale" [2] "float vscale" [2] "float tex1" [1] "float tex2" [0]
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Translate 0 0 1
  ReverseOrientation
  {} {}
AttributeEnd
)",
                                                     shape, alpha));
    };
    const std::string square =
        R"(Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
    "point2 uv" [0 0 1 0 1 1 0 1])";
    const std::string disk = R"(Shape "disk" "float radius" [1])";
    for (const char* integrator : {"direct", "path"}) {
        for (const std::string& shape : {square, disk}) {
            test::RenderSetup s;
            s.integrator = integrator;
            s.spp = 64;
            auto full = test::pixel_mean(test::render_pbrt(scene(shape, ""), s).image, 1);
            auto half =
                test::pixel_mean(test::render_pbrt(scene(shape, R"("texture alpha" "checks")"), s).image, 1);
            EXPECT_NEAR(half.mean, 0.5 * full.mean,
                        4.5 * std::hypot(half.standard_error, 0.5 * full.standard_error) + 1e-5)
                << integrator << ": " << shape;
        }
    }
}

} // namespace
} // namespace illum
