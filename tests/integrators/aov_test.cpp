// The debug passes: albedo shows the material's reflectance; normal shows signed world-space normals,
// which the render loop must keep (only radiance is required to be non-negative).
#include <gtest/gtest.h>

#include "test_support.h"

namespace illum {
namespace {

// Looking down -z at a plane z = 0 whose left half faces +z and right half faces -x (a wall x = 0.3).
const char* kScene = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-1 1 -1 1]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
WorldBegin
Material "diffuse" "rgb reflectance" [0.2 0.4 0.6]
Shape "trianglemesh" "point3 P" [-2 -2 0 2 -2 0 2 2 0 -2 2 0] "integer indices" [0 1 2 0 2 3]
)";

TEST(AovIntegrator, NormalPassKeepsSignedNormals) {
    test::RenderSetup s;
    s.integrator = "normal";
    s.spp = 2;
    auto r = test::render_pbrt(kScene, s);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    // The plane's normal is +z here; flip the camera to the other side to see -z.
    EXPECT_EQ(r.image(3, 3), Color3(0, 0, 1));
    std::string below = kScene;
    below.replace(below.find("LookAt 0 0 5"), 12, "LookAt 0 0 -5");
    auto r2 = test::render_pbrt(below, s);
    EXPECT_EQ(r2.nonfinite_samples, 0u);
    EXPECT_EQ(r2.image(3, 3), Color3(0, 0, 1)) << "the geometric normal does not depend on the viewer";
}

TEST(AovIntegrator, NegativeNormalComponentsSurvive) {
    std::string scene = kScene;
    scene += "Shape \"trianglemesh\" \"point3 P\" [0.3 -2 0 0.3 2 0 0.3 2 3 0.3 -2 3] \"integer indices\" [0 "
             "2 1 0 3 2]\n";
    // Seen from the side: the wall's normal (±x) has a negative component for one orientation.
    scene.replace(scene.find("LookAt 0 0 5  0 0 0  0 1 0"), 26, "LookAt 5 0 1  0 0 1  0 0 1");
    test::RenderSetup s;
    s.integrator = "normal";
    s.spp = 1;
    auto r = test::render_pbrt(scene, s);
    EXPECT_EQ(r.nonfinite_samples, 0u) << "signed values are not failures";
    bool any_negative = false;
    for (std::size_t i = 0; i < r.image.pixel_count(); ++i) any_negative |= r.image.data()[i].has_negative();
    EXPECT_TRUE(any_negative);
}

TEST(AovIntegrator, AlbedoPassShowsReflectance) {
    test::RenderSetup s;
    s.integrator = "albedo";
    s.spp = 1;
    auto r = test::render_pbrt(kScene, s);
    EXPECT_EQ(r.image(4, 4), Color3(0.2f, 0.4f, 0.6f));
}

} // namespace
} // namespace illum
