// pbrt-v4's texture mappings (mapping.h) and the textures without noise (pbrt_textures.h): each formula at
// points where its value is known, and a scene using every one of them builds without a warning. The
// renders against pbrt-v4's are in docs/verification.md ("Texture mappings").
#include <gtest/gtest.h>

#include <cmath>

#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/texture/mapping.h"
#include "illum/texture/pbrt_textures.h"

namespace illum {
namespace {

TextureEvalContext at(Point3f p, Normal3f n = Normal3f(0, 0, 1), Point2f uv = {0, 0}) {
    TextureEvalContext c;
    c.p = p;
    c.n = n;
    c.uv = uv;
    return c;
}

void expect_st(Point2f st, float s, float t) {
    EXPECT_NEAR(st.x, s, 1e-6f);
    EXPECT_NEAR(st.y, t, 1e-6f);
}

TEST(TextureMapping, UVScalesAndOffsets) {
    auto m = TextureMapping2D::uv(2, 3, 0.5f, -1);
    expect_st(m.map(at({}, Normal3f(0, 0, 1), {0.25f, 0.5f})), 1.0f, 0.5f);
}

TEST(TextureMapping, SphericalIsThetaOverPiAndPhiOverTwoPi) {
    auto m = TextureMapping2D::spherical(Transform());
    expect_st(m.map(at({0, 0, 2})), 0, 0);         // +z: θ = 0
    expect_st(m.map(at({3, 0, 0})), 0.5f, 0);      // +x: θ = π/2, φ = 0
    expect_st(m.map(at({0, 1, 0})), 0.5f, 0.25f);  // +y: φ = π/2
    expect_st(m.map(at({0, -1, 0})), 0.5f, 0.75f); // -y: φ = 3π/2 (in [0, 2π))
    expect_st(m.map(at({0, 0, -1})), 1, 0);        // -z: θ = π
    // In the texture's space: a texture defined under Translate 0 0 5 sees (0, 0, 6) as +z.
    auto moved = TextureMapping2D::spherical(Transform::translate({0, 0, 5}).inverse());
    expect_st(moved.map(at({0, 0, 6})), 0, 0);
    expect_st(moved.map(at({0, 0, 4})), 1, 0);
}

TEST(TextureMapping, CylindricalIsAngleAndHeight) {
    auto m = TextureMapping2D::cylindrical(Transform());
    expect_st(m.map(at({1, 0, 0.3f})), 0.5f, 0.3f); // (π + 0) / 2π
    expect_st(m.map(at({0, 1, -2})), 0.75f, -2);    // (π + π/2) / 2π
    expect_st(m.map(at({-1, -1e-7f, 1})), 0.0f, 1); // just below the seam at atan2 = -π
}

TEST(TextureMapping, PlanarProjectsOntoTwoVectors) {
    auto m = TextureMapping2D::planar(Transform(), {1, 0, 0}, {0, 0, 2}, 0.25f, -0.5f);
    expect_st(m.map(at({3, 7, 1})), 3.25f, 1.5f);
}

// Constant float textures for the corners and checks.
struct Value final : FloatTexture {
    explicit Value(float v) : v(v) {}
    float evaluate(const TextureEvalContext&) const override { return v; }
    float v;
};

TEST(Textures, BilerpInterpolatesTheCorners) {
    Value v00(1), v01(2), v10(3), v11(5);
    BilerpTex<FloatTexture, float> t(&v00, &v01, &v10, &v11, TextureMapping2D::uv(1, 1, 0, 0));
    EXPECT_FLOAT_EQ(t.evaluate(at({}, {0, 0, 1}, {0, 0})), 1);
    EXPECT_FLOAT_EQ(t.evaluate(at({}, {0, 0, 1}, {0, 1})), 2); // v01: s = 0, t = 1
    EXPECT_FLOAT_EQ(t.evaluate(at({}, {0, 0, 1}, {1, 0})), 3); // v10: s = 1, t = 0
    EXPECT_FLOAT_EQ(t.evaluate(at({}, {0, 0, 1}, {1, 1})), 5);
    EXPECT_FLOAT_EQ(t.evaluate(at({}, {0, 0, 1}, {0.5f, 0.5f})), 2.75f);
}

TEST(Textures, DirectionMixWeighsByTheNormal) {
    Value a(10), b(2);
    Vector3f dir = normalize(Vector3f(0, 0.6f, 0.8f));
    DirectionMixTex<FloatTexture, float> t(&a, &b, dir);
    EXPECT_FLOAT_EQ(t.evaluate(at({}, Normal3f(0, 0, 1))), 0.8f * 10 + 0.2f * 2);
    EXPECT_FLOAT_EQ(t.evaluate(at({}, Normal3f(0, 0, -1))), 0.8f * 10 + 0.2f * 2); // |n · dir|
    EXPECT_FLOAT_EQ(t.evaluate(at({}, Normal3f(1, 0, 0))), 2);
}

TEST(Textures, SolidCheckerboardParity) {
    Value a(1), b(0);
    Checkerboard3D<FloatTexture, float> t(&a, &b, TextureMapping3D(Transform::scale(2, 2, 2).inverse()));
    // Texture space is the point / 2: (0.5, 0.5, 0.5) -> cell (0, 0, 0), even: tex1.
    EXPECT_EQ(t.evaluate(at({1, 1, 1})), 1);
    EXPECT_EQ(t.evaluate(at({3, 1, 1})), 0);    // cell (1, 0, 0)
    EXPECT_EQ(t.evaluate(at({3, 3, 1})), 1);    // cell (1, 1, 0)
    EXPECT_EQ(t.evaluate(at({-1, 1, 1})), 0);   // cell (-1, 0, 0): odd, as pbrt-v4's (-1) % 2 != 0
    EXPECT_EQ(t.evaluate(at({-1, -1, -1})), 0); // (-1, -1, -1): sum -3
}

// A constant colour's uplifts are computed once; they are the per-hit uplifts of its value, in every
// colour space, in spectral and RGB mode (a negative component clamps to 0 as uplift_unbounded does).
TEST(Textures, ConstantColourUpliftsAreThoseOfItsValue) {
    for (Color3 c : {Color3(0.2f, 0.9f, 0.4f), Color3(1.4f, 2.6f, 3.1f), Color3(-0.5f, 0.3f, 7.0f)}) {
        ConstantColorTexture t(c);
        for (int i = 0; i < RGBColorSpace::kCount; ++i)
            for (float u : {0.1f, 0.55f}) {
                SampledWavelengths w = SampledWavelengths::sample_visible(u, &RGBColorSpace::by_index(i));
                SampledSpectrum unbounded = t.unbounded(at({}), w), expected = uplift_unbounded(c, w);
                SampledSpectrum albedo = t.albedo(at({}), w), expected_albedo = uplift_albedo(c, w);
                for (int k = 0; k < kSpectrumSamples; ++k) {
                    EXPECT_EQ(unbounded[k], expected[k]) << i << " " << k;
                    EXPECT_EQ(albedo[k], expected_albedo[k]) << i << " " << k;
                }
            }
        SampledWavelengths rgb = SampledWavelengths::rgb_mode();
        EXPECT_EQ(t.unbounded(at({}), rgb).rgb(), c);
    }
}

TEST(Textures, EveryMappingAndTheNewTypesBuildWithoutWarnings) {
    SceneDesc desc = parse_pbrt_string(R"(
WorldBegin
Texture "p" "spectrum" "checkerboard" "string mapping" "planar" "vector3 v1" [1 1 0] "vector3 v2" [0 0 1]
    "float udelta" 0.5 "float vdelta" 0.25 "rgb tex1" [1 0 0]
Texture "s" "float" "bilerp" "string mapping" "spherical" "float v00" 0 "float v11" 1
Texture "c" "spectrum" "checkerboard" "string mapping" "cylindrical"
Texture "d" "spectrum" "directionmix" "texture tex1" "p" "texture tex2" "c" "vector3 dir" [0 0 1]
Texture "k" "spectrum" "checkerboard" "integer dimension" 3
Material "coateddiffuse" "texture reflectance" "d" "texture roughness" "s"
Shape "sphere"
Material "diffuse" "texture reflectance" "k"
Shape "sphere"
)",
                                       "<test>", ".");
    auto scene = build_scene(desc);
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_THROW(
        build_scene(parse_pbrt_string("WorldBegin\nTexture \"x\" \"float\" \"checkerboard\" \"string "
                                      "mapping\" \"conical\"\n",
                                      "<test>", ".")),
        Error);
    EXPECT_THROW(
        build_scene(parse_pbrt_string(
            "WorldBegin\nTexture \"x\" \"float\" \"checkerboard\" \"integer dimension\" 4\n", "<test>", ".")),
        Error);
}

} // namespace
} // namespace illum
