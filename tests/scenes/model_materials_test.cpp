// Every reflection model of the registry is reachable from a scene file by its name.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "illum/bsdf/registry.h"
#include "test_support.h"

namespace illum {
namespace {

std::string sphere_scene(const std::string& material) {
    return fmt::format(R"(
LookAt 0 -4 1  0 0 0.5  0 0 1
Camera "perspective" "float fov" [30]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
WorldBegin
LightSource "infinite" "rgb L" [0.5 0.5 0.5]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4]
  Translate 0 -1 4
  Shape "sphere" "float radius" [0.5]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.4 0.4 0.4]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
{}
Translate 0 0 0.5
Shape "sphere" "float radius" [0.5]
)",
                       material);
}

TEST(ModelMaterials, EveryModelRendersFromASceneFile) {
    for (const ModelSpec& spec : bxdf_models()) {
        std::string material = fmt::format("Material \"{}\"", spec.name);
        if (spec.name == "merl") material += R"( "string file" "synthetic:0.2")";
        if (spec.name == "measured") material += R"( "string filename" "synthetic:0.2")";
        test::RenderSetup s;
        s.spp = 4;
        RenderResult r = test::render_pbrt(sphere_scene(material), s);
        EXPECT_EQ(r.nonfinite_samples, 0u) << spec.name;
        EXPECT_FALSE(r.image.has_non_finite()) << spec.name;
        EXPECT_GT(r.image.channel_mean().g, 0.0f) << spec.name;
    }
}

TEST(ModelMaterials, RegistryLambertIsPbrtDiffuse) {
    test::RenderSetup s;
    s.spp = 4;
    Image a =
        test::render_pbrt(sphere_scene(R"(Material "lambert" "rgb reflectance" [0.2 0.5 0.7])"), s).image;
    Image b =
        test::render_pbrt(sphere_scene(R"(Material "diffuse" "rgb reflectance" [0.2 0.5 0.7])"), s).image;
    EXPECT_TRUE(a == b) << "the same model, sampled the same way, gives the same pixels";
}

// A textured parameter is evaluated per hit and the model placed in the arena; with a constant texture it
// must give the very pixels of the constant parameter (same model, same sampling).
TEST(ModelMaterials, TexturedParametersMatchConstantOnes) {
    test::RenderSetup s;
    s.spp = 4;
    for (const char* model : {"oren-nayar", "ward", "phong", "rough-conductor"}) {
        const ModelSpec& spec = find_bxdf_model(model);
        std::string rgb_param;
        for (const ParamSpec& p : spec.params)
            if (p.kind == ParamKind::Rgb && rgb_param.empty()) rgb_param = p.name;
        ASSERT_FALSE(rgb_param.empty()) << model;
        std::string constant = fmt::format(R"(Material "{}" "rgb {}" [0.3 0.2 0.1])", model, rgb_param);
        std::string textured = fmt::format(R"(Texture "t" "spectrum" "constant" "rgb value" [0.3 0.2 0.1]
Material "{}" "texture {}" "t")",
                                           model, rgb_param);
        Image a = test::render_pbrt(sphere_scene(constant), s).image;
        Image b = test::render_pbrt(sphere_scene(textured), s).image;
        EXPECT_TRUE(a == b) << model << " " << rgb_param;
    }
}

TEST(ModelMaterials, CheckerboardAndClampedTextures) {
    test::RenderSetup s;
    s.spp = 4;
    // A checkerboard of two reflectances on the sphere: both levels show.
    std::string checker = R"(Texture "lo" "spectrum" "constant" "rgb value" [0.05 0.05 0.05]
Texture "hi" "spectrum" "constant" "rgb value" [0.9 0.9 0.9]
Texture "c" "spectrum" "checkerboard" "texture tex1" "lo" "texture tex2" "hi" "float uscale" [8] "float vscale" [8]
Material "oren-nayar" "texture reflectance" "c" "float sigma" [20])";
    // Both levels show: the image lies well between the all-dark and the all-bright sphere.
    float mid = test::render_pbrt(sphere_scene(checker), s).image.channel_mean().g;
    float lo =
        test::render_pbrt(
            sphere_scene(R"(Material "oren-nayar" "rgb reflectance" [0.05 0.05 0.05] "float sigma" [20])"), s)
            .image.channel_mean()
            .g;
    float hi =
        test::render_pbrt(
            sphere_scene(R"(Material "oren-nayar" "rgb reflectance" [0.9 0.9 0.9] "float sigma" [20])"), s)
            .image.channel_mean()
            .g;
    EXPECT_GT(mid, lo + 0.2f * (hi - lo));
    EXPECT_LT(mid, hi - 0.2f * (hi - lo));
    // A texture beyond the parameter's range is clamped to it: reflectance 5 acts as 1.
    std::string five = R"(Texture "f" "spectrum" "constant" "rgb value" [5 5 5]
Material "oren-nayar" "texture reflectance" "f")";
    Image a = test::render_pbrt(sphere_scene(five), s).image;
    Image b = test::render_pbrt(sphere_scene(R"(Material "oren-nayar" "rgb reflectance" [1 1 1])"), s).image;
    EXPECT_TRUE(a == b);
}

// Where textures break a model's energy constraint (Ward: rho_d + rho_s <= 1), the pair is scaled down to
// sum to 1 at that point, rather than the constructor failing there: rho_d 0.9 with rho_s 0.5 renders as
// rho_d 0.9/1.4, rho_s 0.5/1.4.
TEST(ModelMaterials, TexturesThatBreakEnergyConservationAreScaledDown) {
    test::RenderSetup s;
    s.spp = 4;
    Image a = test::render_pbrt(sphere_scene(R"(Texture "d" "spectrum" "constant" "rgb value" [0.9 0.9 0.9]
Material "ward" "texture rho_d" "d" "rgb rho_s" [0.5 0.5 0.5])"),
                                s)
                  .image;
    Image b =
        test::render_pbrt(
            sphere_scene(
                R"(Material "ward" "rgb rho_d" [0.642857 0.642857 0.642857] "rgb rho_s" [0.357143 0.357143 0.357143])"),
            s)
            .image;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(a.data()[i][c], b.data()[i][c], 1e-4f + 1e-4f * b.data()[i][c]);
}

TEST(ModelMaterials, ParametersAreCheckedWithTheirPosition) {
    try {
        test::render_pbrt(sphere_scene("\n\nMaterial \"ward\" \"float alpha_x\" [-1]"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        // At the parameter itself, not only its material.
        EXPECT_NE(std::string(e.what()).find("<test>:16:17:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("alpha_x"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum
