// pbrt-v4 features that build.cpp maps: materials, textures, spectra, area light parameters, shapes,
// instances.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "illum/radiometry/spectra.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "test_support.h"

namespace illum {
namespace {

std::unique_ptr<Scene> build(const std::string& world, const BuildOptions& o = {}) {
    std::string text =
        "Camera \"perspective\"\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
        "WorldBegin\n" +
        world;
    return build_scene(parse_pbrt_string(text, "<test>", "."), o);
}

TEST(Spectra, ConstantAndIlluminantNormalisation) {
    PiecewiseLinearSpectrum one{{300, 900}, {0.7, 0.7}};
    Color3 c = unbounded_spectrum_to_rgb(one);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], 0.7f, 1e-4f);
    for (double t : {2000.0, 2856.0, 6500.0, 10000.0})
        EXPECT_NEAR(blackbody_rgb(t).luminance(), 1.0f, 0.01f) << t;
    Color3 warm = blackbody_rgb(2856), cool = blackbody_rgb(10000);
    EXPECT_GT(warm.r, warm.b);
    EXPECT_LT(cool.r, cool.b);
    Color3 d65 = blackbody_rgb(6504); // near the sRGB white
    EXPECT_NEAR(d65.r / d65.b, 1.0f, 0.1f);
    EXPECT_TRUE(named_spectrum_rgb("metal-Au-eta").has_value());
    EXPECT_FALSE(named_spectrum_rgb("metal-Xx-eta").has_value());
    EXPECT_NEAR(cie_y(555), 1.0, 0.02); // the photopic peak
}

TEST(PbrtMaterials, EveryMaterialTypeBuildsAndShades) {
    auto s = build(R"(
Texture "c" "spectrum" "checkerboard" "rgb tex1" [1 0 0]
Texture "f" "float" "scale" "float tex" 0.5 "float scale" 0.2
Texture "m" "spectrum" "mix" "texture tex1" "c" "rgb tex2" [0 1 0] "float amount" 0.3
MakeNamedMaterial "a" "string type" "conductor" "spectrum eta" "metal-Au-eta" "spectrum k" "metal-Au-k" "float roughness" 0.1
MakeNamedMaterial "b" "string type" "dielectric" "spectrum eta" "glass-BK7" "texture roughness" "f"
MakeNamedMaterial "mx" "string type" "mix" "string materials" ["a" "b"] "float amount" 0.5
Material "coateddiffuse" "texture reflectance" "m"
Shape "sphere"
Material "coatedconductor" "spectrum conductor.eta" "metal-Cu-eta" "spectrum conductor.k" "metal-Cu-k"
Shape "sphere"
Material "conductor" "rgb reflectance" [0.9 0.5 0.2]
Shape "sphere"
Material "thindielectric"
Shape "sphere"
Material "diffusetransmission"
Shape "sphere"
Material "interface"
Shape "sphere"
NamedMaterial "mx"
Shape "sphere"
)");
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_GE(s->materials.size(), 9u);
    SurfaceHit hit;
    hit.p = {0, 0, 1};
    hit.n = hit.ns = Normal3f(0, 0, 1);
    hit.dpdu = {1, 0, 0};
    hit.wo = {0, 0.6f, 0.8f};
    hit.uv = {0.25f, 0.25f};
    ScratchArena arena;
    SampledWavelengths lambda = SampledWavelengths::rgb_mode();
    int empty = 0;
    for (const auto& m : s->materials) {
        arena.reset();
        BSDF b = m->bsdf(hit, lambda, arena);
        if (!b) {
            ++empty;
            continue;
        }
        auto smp = b.sample(hit.wo, 0.3f, {0.4f, 0.6f});
        if (smp) {
            EXPECT_TRUE(smp->f.rgb().is_finite());
        }
    }
    EXPECT_EQ(empty, 1); // interface
}

// pbrt-v4's thindielectric is the registry's thin-dielectric under its pbrt-v4 name: a named glass's index
// is its RGB mean without a warning, another spectrum is warned, a textured index is evaluated per hit
// (it was rendered with 1.5, warned), and an index of 0 is an error rather than clamped.
TEST(PbrtMaterials, ThinDielectricIsAnAliasOfTheRegistryModel) {
    auto glass = build("Material \"thindielectric\" \"spectrum eta\" \"glass-BK7\"\nShape \"sphere\"\n");
    EXPECT_TRUE(glass->warnings.empty()) << glass->warnings.front();
    auto sampled =
        build("Material \"thindielectric\" \"spectrum eta\" [400 1.6 700 1.4]\nShape \"sphere\"\n");
    ASSERT_EQ(sampled->warnings.size(), 1u);
    EXPECT_NE(sampled->warnings[0].find("rendered with its mean"), std::string::npos) << sampled->warnings[0];
    auto textured =
        build(R"(Texture "e" "float" "checkerboard" "float uscale" 2 "float tex1" 1.2 "float tex2" 2.4
Material "thindielectric" "texture eta" "e"
Shape "sphere"
)");
    EXPECT_TRUE(textured->warnings.empty()) << textured->warnings.front();
    // At uv (0.25, 0.25) the checkerboard gives 1.2, at (0.75, 0.25) 2.4: a thin pane reflects more at 2.4.
    SurfaceHit hit;
    hit.n = hit.ns = Normal3f(0, 0, 1);
    hit.dpdu = {1, 0, 0};
    hit.wo = {0, 0, 1};
    ScratchArena arena;
    SampledWavelengths lambda = SampledWavelengths::rgb_mode();
    auto reflectance = [&](float u) {
        hit.uv = {u, 0.25f};
        BSDF b = textured->materials.front()->bsdf(hit, lambda, arena);
        auto s = b.sample(hit.wo, 0.0f, {0.5f, 0.5f}); // uc = 0 picks reflection
        EXPECT_TRUE(s && s->is_reflection());
        return s ? s->pdf.value : 0.0f; // the lobe's probability is the pane's reflectance
    };
    EXPECT_LT(reflectance(0.25f), reflectance(0.75f));
    EXPECT_THROW(build("Material \"thindielectric\" \"float eta\" 0\nShape \"sphere\"\n"), Error);
}

TEST(PbrtMaterials, ConductorReflectanceIsTheNormalIncidenceFresnel) {
    auto s = build("Material \"conductor\" \"rgb reflectance\" [0.9 0.5 0.2]\nShape \"sphere\"\n");
    SurfaceHit hit;
    Color3 a = s->materials.front()->albedo(hit);
    EXPECT_NEAR(a.r, 0.9f, 1e-3f);
    EXPECT_NEAR(a.g, 0.5f, 1e-3f);
    EXPECT_NEAR(a.b, 0.2f, 1e-3f);
}

TEST(PbrtMaterials, UnknownAndUnsupportedTypes) {
    EXPECT_THROW(build("Material \"plastic\"\nShape \"sphere\"\n"), Error);
    // "measured" was approximated by a grey diffuse material; it is read now (tests/scenes/
    // measured_scene_test.cpp) and needs its file.
    EXPECT_THROW(build("Material \"measured\"\nShape \"sphere\"\n"), Error);
    BuildOptions strict;
    strict.strict = true;
    auto s = build("Material \"measured\" \"string filename\" \"synthetic:0.3\"\nShape \"sphere\"\n", strict);
    EXPECT_TRUE(s->warnings.empty());
}

TEST(PbrtMaterials, CoatedLayerParametersAreReadWithoutWarnings) {
    // pbrt-v4's full parameter set of both coated materials is understood: no "unused" or "unsupported".
    auto s = build(R"(Material "coateddiffuse" "float roughness" [0.1] "float thickness" [0.2]
    "rgb albedo" [0.5 0.4 0.3] "float g" [0.3] "integer maxdepth" [12] "integer nsamples" [2]
Shape "sphere"
Material "coatedconductor" "float interface.roughness" [0.05] "float conductor.roughness" [0.2]
    "spectrum conductor.eta" "metal-Au-eta" "spectrum conductor.k" "metal-Au-k" "float thickness" [0.05]
    "rgb albedo" [0.2 0.2 0.2] "float g" [-0.2]
Shape "sphere"
)");
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    try {
        build("Material \"coateddiffuse\" \"float thickness\" [-1]\nShape \"sphere\"\n");
        ADD_FAILURE() << "negative thickness accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("thickness"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).rfind("<test>:4:", 0), 0u) << e.what(); // file:line:column
    }
}

TEST(PbrtAreaLights, PowerGivesRadiancePerPrimitiveArea) {
    // A one-sided unit-radius sphere of power 4π² W: L = P / (π A) = 4π² / (π 4π) = 1.
    auto s =
        build("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"float power\" 39.4784176\n"
              "Shape \"sphere\"\nAttributeEnd\n");
    ASSERT_EQ(s->lights.size(), 1u);
    Power3 p = s->lights.front()->power();
    EXPECT_NEAR(p.rgb().g, 39.478f, 0.05f);
}

TEST(PbrtShapes, BilinearMeshCylinderAndInstances) {
    auto s = build(R"(
ObjectBegin "q"
Shape "bilinearmesh" "point3 P" [0 0 0 1 0 0 0 1 0 1 1 0]
ObjectEnd
ObjectInstance "q"
AttributeBegin
Translate 0 0 2
ObjectInstance "q"
AttributeEnd
Shape "cylinder"
Shape "sphere" "float alpha" 0
)");
    EXPECT_EQ(s->accelerator.triangle_count(), 0u)
        << "the prototype's bilinear patch is a patch, not triangles; the cylinder is analytic";
    EXPECT_EQ(s->accelerator.geometry_count(), 3u) << "two instances and the cylinder";
    EXPECT_EQ(s->accelerator.instance_count(), 2u);
    EXPECT_THROW(build("ObjectInstance \"nothing\"\n"), Error);
}

} // namespace
} // namespace illum

namespace illum {
namespace {

// Instancing renders what explicit copies render: a sphere and a triangle defined once and placed three
// times (translated, rotated, scaled) against the same shapes written out with the same transforms.
TEST(PbrtShapes, InstancesRenderLikeCopies) {
    const char* head = R"(
LookAt 0 -8 3  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
WorldBegin
LightSource "infinite" "rgb L" [0.6 0.6 0.6]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [5 5 5]
  Translate 0 0 5
  Shape "sphere" "float radius" [0.5]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
)";
    const char* object = R"(
  Material "diffuse" "rgb reflectance" [0.8 0.3 0.2]
  Shape "sphere" "float radius" [0.4]
  Shape "trianglemesh" "point3 P" [0.5 -0.3 0 1.1 -0.3 0 1.1 0.3 0.6] "integer indices" [0 1 2]
)";
    // (Not a mirror: pbrt flips a mirrored copy's normals for the handedness of its own transform, but
    // carries an instance's hit out through the instance transform without that flip, so the two differ in
    // sign.)
    const char* places[] = {"Translate -2 0 0.4", "Translate 0 0 0.4 Rotate 40 0 0 1",
                            "Translate 2 0 0.4 Rotate 70 1 1 0 Scale 1.3 1.3 1.3"};
    std::string instanced = std::string(head) + "ObjectBegin \"o\"" + object + "ObjectEnd\n";
    std::string copies = head;
    for (const char* place : places) {
        instanced += fmt::format("AttributeBegin\n{}\nObjectInstance \"o\"\nAttributeEnd\n", place);
        copies += fmt::format("AttributeBegin\n{}\n{}AttributeEnd\n", place, object);
    }
    // First hits (geometry, normals through the mirrored instance, materials) agree up to float rounding
    // at silhouettes.
    for (const char* pass : {"normal", "albedo"}) {
        test::RenderSetup s;
        s.integrator = pass;
        s.spp = 4;
        Image a = test::render_pbrt(instanced, s).image, b = test::render_pbrt(copies, s).image;
        int differing = 0;
        for (std::size_t i = 0; i < a.pixel_count(); ++i)
            for (int c = 0; c < 3; ++c) differing += std::abs(a.data()[i][c] - b.data()[i][c]) > 1e-3f;
        EXPECT_LE(differing, int(a.pixel_count() / 100)) << pass << ": values that differ beyond rounding";
    }
    // Radiance: once rounding differs, paths diverge, so the images agree within noise.
    test::RenderSetup s;
    s.spp = 16;
    Image a = test::render_pbrt(instanced, s).image, b = test::render_pbrt(copies, s).image;
    auto ma = test::pixel_mean(a, 1), mb = test::pixel_mean(b, 1);
    EXPECT_NEAR(ma.mean, mb.mean, 4.5 * std::hypot(ma.standard_error, mb.standard_error));
}

} // namespace
} // namespace illum
