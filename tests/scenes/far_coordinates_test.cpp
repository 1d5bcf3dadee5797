// Rays Embree cannot trace (a coordinate beyond ±1.844e18, or NaN) hit nothing instead of tripping
// Embree's ray.valid() assertion, which aborts the process. Found by the libFuzzer target
// (fuzz/pbrt_scene_fuzz.cpp): a point light at z ≈ 9.2e18 made every shadow ray abort the render.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_support.h"

namespace illum {
namespace {

TEST(FarCoordinates, PointLightBeyondEmbreesRangeDoesNotAbortTheRender) {
    for (const char* integrator : {"path", "direct"}) {
        SCOPED_TRACE(integrator);
        test::RenderSetup s;
        s.integrator = integrator;
        s.spp = 2;
        auto r = test::render_pbrt(
            test::irradiance_receiver(
                R"(LightSource "point" "point3 from" [0 0 9223372036854775804] "rgb I" [5 5 5])", integrator,
                4),
            s);
        EXPECT_EQ(r.nonfinite_samples, 0u);
        EXPECT_NEAR(r.image.channel_mean().g, 0, 1e-30) << "I / d² vanishes at d = 9.2e18";
    }
}

TEST(FarCoordinates, CameraBeyondEmbreesRangeSeesNothing) {
    auto r = test::render_pbrt(R"(
LookAt 0 0 1e19  0 0 0  0 1 0
Camera "perspective"
Film "rgb" "integer xresolution" [4] "integer yresolution" [4]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Shape "sphere" "float radius" [1]
AttributeEnd
)",
                               {});
    EXPECT_EQ(r.image.channel_mean().g, 0);
}

TEST(FarCoordinates, UntraceableRaysHitNothing) {
    SceneDesc desc = parse_pbrt_string(R"(
WorldBegin
Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
)",
                                       "<test>", ".");
    auto scene = build_scene(desc);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    SurfaceHit hit;
    Ray good{{0, 0, 1}, {0, 0, -1}};
    ASSERT_TRUE(scene->accelerator.intersect(good, &hit));
    ASSERT_TRUE(scene->accelerator.occluded(good));
    for (Ray bad :
         {Ray{{0, 0, 1}, {0, nan, -1}}, Ray{{nan, 0, 1}, {0, 0, -1}}, Ray{{0, 0, 1e19f}, {0, 0, -1}},
          Ray{{0, 0, 1}, {0, 0, -2e18f}}, Ray{{0, 0, 1}, {0, 0, -1}, nan}}) {
        EXPECT_FALSE(scene->accelerator.intersect(bad, &hit));
        EXPECT_FALSE(scene->accelerator.occluded(bad));
        EXPECT_EQ(scene->accelerator.intersect_distance(bad), kInfinity);
    }
}

} // namespace
} // namespace illum
