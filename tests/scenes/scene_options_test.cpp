// pbrt-v4's Option directives: each changes what it claims (seed, disablepixeljitter,
// disablewavelengthjitter, forcediffuse), the accepted ones change nothing else, the others warn, and bad
// ones are positioned errors.
#include <gtest/gtest.h>

#include <algorithm>

#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

std::unique_ptr<Scene> build_text(const std::string& text) {
    return build_scene(parse_pbrt_string(text, "o.pbrt", "."));
}

const char* kEnvironment = R"(Camera "perspective"
Film "rgb" "integer xresolution" 6 "integer yresolution" 4
WorldBegin
LightSource "infinite" "rgb L" [0.25 0.5 0.75]
)";

TEST(SceneOptions, BothSpellingsAreRead) {
    // pbrt-v4's parser reads `Option "name" value` (and rejects the typed form); illum reads both.
    auto a = build_text(std::string("Option \"integer seed\" 7\nOption \"bool disablepixeljitter\" true\n"
                                    "Option \"string rendercoordsys\" \"world\"\n") +
                        kEnvironment);
    auto b = build_text(std::string("Option \"seed\" 7\nOption \"disablepixeljitter\" true\n"
                                    "Option \"rendercoordsys\" \"cameraworld\"\n") +
                        kEnvironment);
    for (const Scene* s : {a.get(), b.get()}) {
        ASSERT_TRUE(s->request.seed.has_value());
        EXPECT_EQ(*s->request.seed, 7u);
        EXPECT_TRUE(s->request.disable_pixel_jitter);
        EXPECT_FALSE(s->request.disable_wavelength_jitter);
        EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    }
    EXPECT_FALSE(build_text(kEnvironment)->request.seed.has_value());
}

TEST(SceneOptions, DisablePixelJitterSamplesThePixelCentre) {
    // An orthographic film of 4 x 1 pixels over camera x in [-2, 2]; an emitter covers x > 0.2, so pixel 2
    // (x in [0, 1]) is 80% covered: 0.8 L with the box filter's jitter, exactly L through its centre.
    auto scene = [](bool disable) {
        return std::string("Option \"bool disablepixeljitter\" ") + (disable ? "true" : "false") + R"(
Camera "orthographic" "float screenwindow" [-2 2 -0.5 0.5]
Film "rgb" "integer xresolution" 4 "integer yresolution" 1
PixelFilter "box"
Sampler "sobol" "integer pixelsamples" 64
WorldBegin
AreaLightSource "diffuse" "rgb L" [2 2 2] "bool twosided" true
Shape "bilinearmesh" "point3 P" [0.2 -5 1  5 -5 1  0.2 5 1  5 5 1]
)";
    };
    Image jittered = test::render_pbrt(scene(false)).image;
    Image centred = test::render_pbrt(scene(true)).image;
    EXPECT_NEAR(jittered(2, 0).g, 1.6f, 0.05f);
    EXPECT_EQ(centred(2, 0).g, 2.0f);
    EXPECT_EQ(centred(1, 0).g, 0.0f);
    EXPECT_EQ(centred(3, 0).g, 2.0f);
}

TEST(SceneOptions, DisableWavelengthJitterGivesEverySampleTheSameWavelengths) {
    // A uniform environment in spectral mode: each pixel's value depends only on its samples'
    // wavelengths, so with them fixed every pixel is the same; with them jittered, pixels differ.
    test::RenderSetup spectral;
    spectral.spectral = true;
    spectral.spp = 4;
    Image fixed = test::render_pbrt(
                      std::string("Option \"bool disablewavelengthjitter\" true\n") + kEnvironment, spectral)
                      .image;
    Image jittered = test::render_pbrt(kEnvironment, spectral).image;
    bool differ = false;
    for (int y = 0; y < fixed.height(); ++y)
        for (int x = 0; x < fixed.width(); ++x) {
            EXPECT_EQ(fixed(x, y), fixed(0, 0)) << x << "," << y;
            differ = differ || jittered(x, y) != jittered(0, 0);
        }
    EXPECT_TRUE(differ);
    // In RGB mode there are no wavelengths to fix: the image is unchanged.
    EXPECT_EQ(
        test::render_pbrt(std::string("Option \"bool disablewavelengthjitter\" true\n") + kEnvironment).image,
        test::render_pbrt(kEnvironment).image);
}

TEST(SceneOptions, ForceDiffuseMakesAMirrorLambertianOfItsAlbedo) {
    // A mirror (conductor of normal-incidence reflectance r = 0.5) seen head-on by an orthographic camera,
    // lit by a point light of intensity π at the camera's origin, 1 away: a mirror cannot show the point
    // light (black); forced diffuse, it is Lambertian of albedo ρ(wo) = F(1) = r, so L = r/π · π cos/d² =
    // 0.5 (1 + s²)^(-3/2) at film offset s <= 0.005 (within 1e-4).
    auto scene = [](bool force) {
        return std::string("Option \"bool forcediffuse\" ") + (force ? "true" : "false") + R"(
Camera "orthographic" "float screenwindow" [-0.01 0.01 -0.01 0.01]
Film "rgb" "integer xresolution" 2 "integer yresolution" 2
Integrator "path" "integer maxdepth" 1
WorldBegin
LightSource "point" "rgb I" [3.14159265 3.14159265 3.14159265] "point3 from" [0 0 0]
Material "conductor" "rgb reflectance" [0.5 0.5 0.5] "float roughness" 0
Shape "bilinearmesh" "point3 P" [-5 -5 1  -5 5 1  5 -5 1  5 5 1]
)";
    };
    // Nothing scatters specularly any more (so volpath traces no caustics from the lights).
    auto forced = build_text(scene(true));
    for (const auto& m : forced->materials) EXPECT_FALSE(m->may_be_specular);
    auto plain = build_text(scene(false));
    EXPECT_TRUE(std::any_of(plain->materials.begin(), plain->materials.end(),
                            [](const auto& m) { return m->may_be_specular; }));
    Image mirror = test::render_pbrt(scene(false)).image;
    Image diffuse = test::render_pbrt(scene(true)).image;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(mirror(x, y)[c], 0.0f);
                EXPECT_NEAR(diffuse(x, y)[c], 0.5f, 1e-4f) << x << "," << y;
            }
}

TEST(SceneOptions, SeedIsTheSamplesSeed) {
    auto scene = build_text(std::string("Option \"integer seed\" 12\n") + kEnvironment);
    EXPECT_EQ(scene->request.seed.value_or(0), 12u);
    test::expect_error([] { build_text(std::string("Option \"integer seed\" -3\n") + kEnvironment); },
                       "o.pbrt:1:", "non-negative integer");
}

TEST(SceneOptions, RecognisedButInertOptionsWarnPrecisely) {
    auto scene = build_text(std::string("Option \"bool pixelstats\" true\nOption \"bool wavefront\" true\n"
                                        "Option \"float displacementedgescale\" 2\n"
                                        "Option \"bool disabletexturefiltering\" true\n") +
                            kEnvironment);
    ASSERT_EQ(scene->warnings.size(), 2u);
    EXPECT_NE(scene->warnings[0].find("o.pbrt:1:"), std::string::npos) << scene->warnings[0];
    EXPECT_NE(scene->warnings[0].find("\"pixelstats\" is not used"), std::string::npos);
    EXPECT_NE(scene->warnings[1].find("\"wavefront\" is not used"), std::string::npos);
    // "displacementedgescale" is used: it scales plymesh's "edgelength" (tests/geometry/displace_mesh_test.cpp).
    EXPECT_EQ(scene->request.displacement_edge_scale, 2.0f);
    BuildOptions strict;
    strict.strict = true;
    EXPECT_THROW(build_scene(parse_pbrt_string(std::string("Option \"bool wavefront\" true\n") + kEnvironment,
                                               "o.pbrt", "."),
                             strict),
                 Error);
}

TEST(SceneOptions, BadOptionsArePositionedErrors) {
    auto fails = [](const std::string& option, const std::string& phrase) {
        test::expect_error([&] { build_text(option + "\n" + kEnvironment); }, "o.pbrt:1:", phrase);
    };
    fails("Option \"bool nosuchoption\" true", "unknown option \"nosuchoption\"");
    fails("Option \"string rendercoordsys\" \"screen\"", "unknown rendering coordinate system");
    fails("Option \"integer disablepixeljitter\" 1", "expects true or false");
    fails("Option \"forcediffuse\" \"yes\"", "expects true or false");
}

} // namespace
} // namespace illum
