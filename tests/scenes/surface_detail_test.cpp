// pbrt-v4's surface detail (bsdf/surface_detail.h): bump mapping by finite differences of a displacement
// texture and tangent-space normal maps, checked against closed forms at single hits, in the normal AOV,
// and in radiance (a Lambertian surface under a distant light reflects ρ/π E cos θ to the shading normal).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>

#include "illum/bsdf/surface_detail.h"
#include "illum/geometry/sphere.h"
#include "illum/image/image_io.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "test_support.h"

namespace illum {
namespace {

namespace fs = std::filesystem;

constexpr double kDeg = 3.14159265358979323846 / 180;

// d(u, v) = a sin(k u).
class SineInU final : public FloatTexture {
public:
    SineInU(float a, float k) : a_(a), k_(k) {}
    float evaluate(const TextureEvalContext& c) const override { return a_ * std::sin(k_ * c.uv.x); }

private:
    float a_, k_;
};

// A hit on the plane z = 0 parameterised by p = (u, v, 0) (or by the tangents given).
SurfaceHit plane_hit(Point2f uv, Vector3f dpdu = {1, 0, 0}, Vector3f dpdv = {0, 1, 0}) {
    SurfaceHit h;
    h.p = {uv.x, uv.y, 0};
    h.n = h.ns = {0, 0, 1};
    h.uv = uv;
    h.dpdu = dpdu;
    h.dpdv = dpdv;
    return h;
}

void expect_near(Normal3f a, Vector3f b, float tol, const std::string& what = "") {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

std::shared_ptr<const Image> constant_map(Color3 c) { return std::make_shared<const Image>(4, 4, c); }

// The texel that encodes the tangent-space normal (sin θ, 0, cos θ): tilted by θ towards ∂p/∂u.
Color3 tilted_texel(double theta) {
    return {float((std::sin(theta) + 1) / 2), 0.5f, float((std::cos(theta) + 1) / 2)};
}

TEST(BumpMap, SineDisplacementGivesTheAnalyticNormal) {
    // p' = (u, v, a sin(k u)): ∂p'/∂u = (1, 0, a k cos(k u)), so n' ∝ (-a k cos(k u), 0, 1). The forward
    // difference's error in the slope is at most |d''| Δu / 2 = a k² Δu / 2.
    const float a = 0.05f, k = 10;
    SineInU d(a, k);
    SurfaceDetail detail(&d, nullptr);
    const float slope_error = a * k * k * SurfaceDetail::kBumpDelta / 2 + 1e-5f;
    for (float u : {0.0f, 0.1f, 0.3f, 0.45f, 0.7f}) {
        SurfaceHit h = plane_hit({u, 0.2f});
        detail.apply(h);
        Vector3f expected = normalize(Vector3f(-a * k * std::cos(k * u), 0, 1));
        expect_near(h.ns, expected, slope_error, fmt::format("u = {}", u));
        EXPECT_NEAR(h.dpdu.z, a * k * std::cos(k * u), slope_error) << u;
        EXPECT_NEAR(length(h.dpdv - Vector3f(0, 1, 0)), 0, 1e-6f) << u; // d does not vary in v
    }
}

// d(u, v) = a u².
class QuadraticInU final : public FloatTexture {
public:
    explicit QuadraticInU(float a) : a_(a) {}
    float evaluate(const TextureEvalContext& c) const override { return a_ * c.uv.x * c.uv.x; }

private:
    float a_;
};

TEST(BumpMap, StepsByHalfTheFootprintAsPbrtV4) {
    // pbrt-v4's BumpMap steps by Δu = (|∂u/∂x| + |∂u/∂y|) / 2 (.0005 for a zero footprint); the forward
    // difference of d = a u² is exactly a (2u + Δu), so the step shows in ∂p'/∂u's z.
    const float a = 2;
    QuadraticInU d(a);
    SurfaceDetail detail(&d, nullptr);
    const float u = 0.25f;
    struct Case {
        float dudx, dudy, step;
    };
    for (Case c :
         {Case{0, 0, SurfaceDetail::kBumpDelta}, Case{0.02f, -0.01f, 0.015f}, Case{0, 0.1f, 0.05f}}) {
        SurfaceHit h = plane_hit({u, 0.2f});
        h.dudx = c.dudx;
        h.dudy = c.dudy;
        detail.apply(h);
        EXPECT_NEAR(h.dpdu.z, a * (2 * u + c.step), 2e-5f) << c.dudx << " " << c.dudy;
        EXPECT_NEAR(length(h.dpdv - Vector3f(0, 1, 0)), 0, 1e-6f); // d does not vary in v
    }
    EXPECT_TRUE(detail.bumps());
    EXPECT_FALSE(SurfaceDetail(nullptr, constant_map(Color3(0.5f, 0.5f, 1))).bumps());
}

TEST(BumpMap, ConstantDisplacementLeavesTheNormal) {
    ConstantFloatTexture d(0.3f);
    SurfaceDetail detail(&d, nullptr);
    SurfaceHit h = plane_hit({0.3f, 0.6f}, {2, 0.5f, 0}, {-0.3f, 1.5f, 0});
    detail.apply(h);
    expect_near(h.ns, {0, 0, 1}, 1e-6f);
    // On a sphere d ∂n/∂u = d ∂p/∂u / r scales both tangents alike: the normal stays.
    SphereShape sphere(Point3f(1, 2, 3), 2, false);
    for (Vector3f dir :
         {Vector3f(0, 0, -1), normalize(Vector3f(1, 1, -1)), normalize(Vector3f(-1, 0.3f, 0.2f))}) {
        Ray ray{Point3f(1, 2, 3) - dir * 10, dir, kInfinity};
        Crossing c[2];
        ASSERT_GT(sphere.crossings(ray, 0, kInfinity, c), 0);
        SurfaceHit s;
        sphere.fill_hit(float(c[0].t), ray, &s);
        Normal3f n = s.ns;
        detail.apply(s);
        expect_near(s.ns, Vector3f(n), 2e-6f);
    }
}

TEST(BumpMap, PaysNothingWithoutDetail) {
    // A material without detail never touches the hit; a detail is made only for a material that has one.
    SurfaceHit h = plane_hit({0.1f, 0.2f});
    DiffuseMaterial plain(nullptr);
    h.material = &plain;
    EXPECT_FALSE(plain.has_surface_detail);
    EXPECT_EQ(apply_surface_detail(h), &plain);
    expect_near(h.ns, {0, 0, 1}, 0);
}

TEST(NormalMap, FlatMapLeavesTheShadingGeometry) {
    SurfaceDetail detail(nullptr, constant_map(Color3(0.5f, 0.5f, 1.0f)));
    SurfaceHit h = plane_hit({0.3f, 0.6f}, {2, 0, 0}, {0, 3, 0});
    detail.apply(h);
    expect_near(h.ns, {0, 0, 1}, 1e-6f);
    EXPECT_NEAR(length(h.dpdu - Vector3f(2, 0, 0)), 0, 1e-5f);
    EXPECT_NEAR(length(h.dpdv - Vector3f(0, 3, 0)), 0, 1e-5f);
}

TEST(NormalMap, TiltedMapRotatesTheNormalTowardsDpdu) {
    for (double theta : {10.0, 30.0, 60.0}) {
        SurfaceDetail detail(nullptr, constant_map(tilted_texel(theta * kDeg)));
        // A tangent frame that is not the world's: x along ∂p/∂u = (0, 2, 0), so n' = (0, sin θ, cos θ);
        // the lengths of ∂p/∂u and ∂p/∂v are kept.
        SurfaceHit h = plane_hit({0.3f, 0.6f}, {0, 2, 0}, {-1, 0.5f, 0});
        detail.apply(h);
        Vector3f expected(0, float(std::sin(theta * kDeg)), float(std::cos(theta * kDeg)));
        expect_near(h.ns, expected, 1e-5f, fmt::format("θ = {}", theta));
        EXPECT_NEAR(length(h.dpdu), 2, 1e-5f);
        EXPECT_NEAR(length(h.dpdv), std::sqrt(1.25f), 1e-5f);
        EXPECT_NEAR(dot(h.dpdu, Vector3f(h.ns)), 0, 1e-5f);
    }
}

TEST(NormalMap, LooksUpAtUAndOneMinusVWithRepeat) {
    // A 2x2 map whose top-left texel (row 0) tilts towards +x, the others towards -x. pbrt-v4 reads it at
    // (u, 1 - v): texel centres at u, 1 - v in {1/4, 3/4}, so (u, v) = (1/4, 3/4) is the top-left one.
    auto img = std::make_shared<Image>(2, 2, tilted_texel(-40 * kDeg));
    img->at(0, 0) = tilted_texel(40 * kDeg);
    SurfaceDetail detail(nullptr, img);
    for (Point2f uv : {Point2f(0.25f, 0.75f), Point2f(1.25f, -0.25f), Point2f(-2.75f, 3.75f)}) {
        SurfaceHit h = plane_hit(uv);
        detail.apply(h);
        EXPECT_NEAR(h.ns.x, std::sin(40 * kDeg), 1e-4f) << uv.x << " " << uv.y;
    }
    SurfaceHit h = plane_hit({0.75f, 0.75f});
    detail.apply(h);
    EXPECT_NEAR(h.ns.x, -std::sin(40 * kDeg), 1e-4f);
}

// Scene files with normal maps written to a temporary folder.
class SurfaceDetailScenes : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("illum_surface_detail_" + std::to_string(::getpid()));
        fs::create_directories(root_);
        write_image(Image(8, 8, Color3(0.5f, 0.5f, 1.0f)), path("flat.pfm"));
        write_image(Image(8, 8, tilted_texel(25 * kDeg)), path("tilted.pfm"));
    }
    void TearDown() override { fs::remove_all(root_); }
    std::string path(const std::string& name) const { return (root_ / name).string(); }

    // An orthographic view straight down on the unit square around the origin, lit by a distant light
    // from `light_dir` (towards the light), depth 1; `world` adds the surface.
    static std::string lit(const std::string& world, Vector3f light_dir,
                           const std::string& integrator = "direct") {
        return fmt::format(R"(
Integrator "{}" "integer maxdepth" [1]
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-0.5 0.5 -0.5 0.5]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
PixelFilter "box"
WorldBegin
LightSource "distant" "point3 from" [{} {} {}] "point3 to" [0 0 0] "rgb L" [3 3 3]
{}
)",
                           integrator, light_dir.x, light_dir.y, light_dir.z, world);
    }
    static double mean(const Image& img, int c) { return test::pixel_mean(img, c).mean; }
    static test::RenderSetup aov() {
        test::RenderSetup s;
        s.integrator = "normal";
        return s;
    }
    static test::RenderSetup direct() {
        test::RenderSetup s;
        s.integrator = "direct";
        return s;
    }

    fs::path root_;
};

// A 2 x 2 square in z = 0 with uv (0, 0) to (1, 1): ∂p/∂u = (2, 0, 0), ∂p/∂v = (0, 2, 0).
const char* kSquare =
    R"(Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
  "point2 uv" [0 0 1 0 1 1 0 1])";
const char* kPatch = R"(Shape "bilinearmesh" "point3 P" [-1 -1 0 1 -1 0 -1 1 0 1 1 0])";

TEST_F(SurfaceDetailScenes, FlatNormalMapRendersAsNoMap) {
    std::string world = std::string(kSquare) + "\nShape \"sphere\" \"float radius\" 0.3\n";
    std::string plain = lit("Material \"diffuse\"\n" + world, {0.3f, 0.2f, 1}, "path");
    std::string mapped =
        lit(fmt::format("Material \"diffuse\" \"string normalmap\" \"{}\"\n{}", path("flat.pfm"), world),
            {0.3f, 0.2f, 1}, "path");
    test::RenderSetup setup;
    setup.spp = 4;
    setup.max_depth = 3;
    Image a = test::render_pbrt(plain, setup).image, b = test::render_pbrt(mapped, setup).image;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.data()[i][c], b.data()[i][c], 1e-4f * (1 + a.data()[i][c]));
}

TEST_F(SurfaceDetailScenes, TiltedNormalMapInTheNormalAov) {
    // On the square and the bilinear patch ∂p/∂u = +x: n' = (sin 25°, 0, cos 25°) everywhere.
    const Vector3f expected(float(std::sin(25 * kDeg)), 0, float(std::cos(25 * kDeg)));
    for (const char* shape : {kSquare, kPatch}) {
        std::string scene = lit(
            fmt::format("Material \"diffuse\" \"string normalmap\" \"{}\"\n{}", path("tilted.pfm"), shape),
            {0, 0, 1}, "normal");
        Image img = test::render_pbrt(scene, aov()).image;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean(img, c), expected[c], 1e-5) << shape << " channel " << c;
    }
    // A disk of radius 2 at the origin: at a point (x, y, 0) of azimuth φ, ∂p/∂u = 2π (-y, x, 0), so the
    // normal tilts along (-sin φ, cos φ, 0). Pixel (7, 4) is centred on screen (0.4375, -0.0625), which
    // pbrt-v4's LookAt (left-handed camera space) puts at world (-0.4375, -0.0625).
    std::string disk = lit(fmt::format("Material \"diffuse\" \"string normalmap\" \"{}\"\n"
                                       "Shape \"disk\" \"float radius\" 2\n",
                                       path("tilted.pfm")),
                           {0, 0, 1}, "normal");
    Image img = test::render_pbrt(disk, aov()).image;
    Color3 right = img(7, 4);
    float phi = std::atan2(-0.0625f, -0.4375f);
    Vector3f t(-std::sin(phi), std::cos(phi), 0);
    Vector3f n = t * float(std::sin(25 * kDeg)) + Vector3f(0, 0, 1) * float(std::cos(25 * kDeg));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(right[c], n[c], 0.02f) << c; // the box filter averages φ
}

TEST_F(SurfaceDetailScenes, InstancesCarryTheirPartialsToTheWorld) {
    // The square as an object instance turned 90° about z: its ∂p/∂u becomes +y, so the 25° map tilts the
    // normal to (0, sin 25°, cos 25°); the bump d = 0.8 u, likewise turned, to (0, -0.8, 2)/|·|.
    std::string object = fmt::format(R"(
Texture "ramp" "float" "bilerp" "float v00" 0 "float v01" 0 "float v10" 0.8 "float v11" 0.8
ObjectBegin "mapped"
Material "diffuse" "string normalmap" "{}"
{}
ObjectEnd
ObjectBegin "bumped"
Material "diffuse" "texture displacement" "ramp"
{}
ObjectEnd
AttributeBegin
Rotate 90 0 0 1
ObjectInstance "{{}}"
AttributeEnd
)",
                                     path("tilted.pfm"), kSquare, kSquare);
    const Vector3f mapped(0, float(std::sin(25 * kDeg)), float(std::cos(25 * kDeg)));
    const Vector3f bumped = normalize(Vector3f(0, -0.8f, 2));
    for (auto [name, expected] : {std::pair{"mapped", mapped}, std::pair{"bumped", bumped}}) {
        Image img =
            test::render_pbrt(lit(fmt::format(fmt::runtime(object), name), {0, 0, 1}, "normal"), aov()).image;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean(img, c), expected[c], 1e-5) << name << " channel " << c;
    }
}

TEST_F(SurfaceDetailScenes, BumpedAndMappedSurfacesReflectLambertAtThePerturbedNormal) {
    // Lambert under a distant light of irradiance E (at normal incidence): L = ρ/π E max(0, cos) to the
    // shading normal. A flat surface gives ρ/π E cos α for the light at α from the normal, so the ratio of
    // the perturbed to the flat render is cos(angle to n') / cos α, whatever E's convention.
    //
    // The displacement d = a u (pbrt-v4's "bilerp" float texture, 0 at u = 0, a at u = 1) on the square
    // (∂p/∂u = (2, 0, 0)) gives ∂p'/∂u = (2, 0, a): n' = (-a, 0, 2) / √(a² + 4), exact for a linear d.
    const float a = 0.8f;
    const Vector3f light = normalize(Vector3f(-0.6f, 0.2f, 1));
    const Vector3f bumped = normalize(Vector3f(-a, 0, 2));
    const Vector3f mapped(float(std::sin(25 * kDeg)), 0, float(std::cos(25 * kDeg)));
    std::string bilerp = fmt::format("Texture \"ramp\" \"float\" \"bilerp\" \"float v00\" 0 \"float v01\" 0 "
                                     "\"float v10\" {} \"float v11\" {}\n",
                                     a, a);
    for (const char* shape : {kSquare, kPatch}) {
        Image flat =
            test::render_pbrt(lit("Material \"diffuse\"\n" + std::string(shape), light), direct()).image;
        Image bump =
            test::render_pbrt(
                lit(bilerp + "Material \"diffuse\" \"texture displacement\" \"ramp\"\n" + shape, light),
                direct())
                .image;
        Image map = test::render_pbrt(lit(fmt::format("Material \"diffuse\" \"string normalmap\" \"{}\"\n{}",
                                                      path("tilted.pfm"), shape),
                                          light),
                                      direct())
                        .image;
        double f = mean(flat, 1);
        ASSERT_GT(f, 0) << shape;
        EXPECT_NEAR(f, 0.5 / kPi * 3 * light.z, 0.5 / kPi * 3 * light.z * 0.02) << "E = 3 (rgb L [3 3 3])";
        EXPECT_NEAR(mean(bump, 1) / f, dot(bumped, light) / light.z, 1e-4) << shape;
        EXPECT_NEAR(mean(map, 1) / f, dot(mapped, light) / light.z, 1e-4) << shape;
    }
}

TEST_F(SurfaceDetailScenes, MixAppliesTheChosenMaterialsDetail) {
    std::string world = fmt::format(R"(
MakeNamedMaterial "plain" "string type" "diffuse"
MakeNamedMaterial "mapped" "string type" "diffuse" "string normalmap" "{}"
MakeNamedMaterial "m" "string type" "mix" "string materials" ["plain" "mapped"] "float amount" 1
NamedMaterial "m"
{}
)",
                                    path("tilted.pfm"), kSquare);
    Image img = test::render_pbrt(lit(world, {0, 0, 1}, "normal"), aov()).image;
    EXPECT_NEAR(mean(img, 0), std::sin(25 * kDeg), 1e-5);
}

TEST_F(SurfaceDetailScenes, EveryMaterialTakesItWithoutWarnings) {
    // "measured" with its table: the type's text closes the quote and adds the filename parameter.
    for (const char* type :
         {"diffuse", "conductor", "dielectric", "thindielectric", "coateddiffuse", "coatedconductor",
          "diffusetransmission", "subsurface", "measured\" \"string filename\" \"synthetic:0.3", "ward"}) {
        std::string world = fmt::format(R"(
Texture "bumps" "float" "checkerboard" "float uscale" 8 "float vscale" 8 "float tex1" 0 "float tex2" 0.01
Material "{}" "texture displacement" "bumps"
{}
Material "{}" "string normalmap" "{}"
Shape "sphere" "float radius" 0.3
Material "{}" "float displacement" 0.1 "string normalmap" "{}"
Shape "cylinder" "float radius" 0.2
)",
                                        type, kSquare, type, path("tilted.pfm"), type, path("tilted.pfm"));
        std::unique_ptr<Scene> s = build_scene(parse_pbrt_string(lit(world, {0, 0, 1}), "<test>", "."));
        EXPECT_EQ(s->warnings.size(), 0u) << type;
        // A bump map steps by the hit's footprint, so camera rays carry differentials.
        EXPECT_TRUE(s->texture_filtering) << type;
    }
}

TEST_F(SurfaceDetailScenes, BadInputIsAPositionedError) {
    auto error_line = [&](const std::string& world) -> int {
        try {
            build_scene(parse_pbrt_string(lit(world, {0, 0, 1}), "<test>", "."));
        } catch (const Error& e) {
            EXPECT_EQ(e.where().file, "<test>") << e.what();
            return e.where().line;
        }
        ADD_FAILURE() << "no error for " << world;
        return 0;
    };
    // lit() puts `world` on line 9.
    EXPECT_EQ(error_line(fmt::format("Material \"diffuse\" \"string normalmap\" \"{}\"\n{}", path("none.pfm"),
                                     kSquare)),
              9);
    EXPECT_EQ(
        error_line(std::string("Shape \"sphere\"\nMaterial \"diffuse\" \"float normalmap\" 1\n") + kSquare),
        10);
    EXPECT_EQ(
        error_line(std::string("Material \"diffuse\" \"texture displacement\" \"nothing\"\n") + kSquare), 9);
    EXPECT_EQ(error_line(std::string("Material \"diffuse\" \"rgb displacement\" [1 1 1]\n") + kSquare), 9);
}

} // namespace
} // namespace illum
