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
    Image a = test::render_pbrt(sphere_scene(R"(Material "lambert" "rgb reflectance" [0.2 0.5 0.7])"), s).image;
    Image b = test::render_pbrt(sphere_scene(R"(Material "diffuse" "rgb reflectance" [0.2 0.5 0.7])"), s).image;
    EXPECT_TRUE(a == b) << "the same model, sampled the same way, gives the same pixels";
}

TEST(ModelMaterials, ParametersAreCheckedWithTheirPosition) {
    try {
        test::render_pbrt(sphere_scene("\n\nMaterial \"ward\" \"float alpha_x\" [-1]"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("<test>:16:1:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("alpha_x"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum
