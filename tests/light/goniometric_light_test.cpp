// pbrt-v4's goniometric light: its power against the integral of its intensity over the sphere and against
// its photons, pdf_le against sample_le, pbrt-v4's y/z swap, and a constant image rendering as the point
// light of the same intensity.
#include <gtest/gtest.h>

#include "illum/envmap/layout.h"
#include "illum/light/goniometric_light.h"
#include "illum/light/light_factory.h"
#include "illum/light/point_light.h"
#include "illum/math/warp.h"
#include "illum/scene/pbrt/parser.h"
#include "image_lights_support.h"
#include "test_support.h"

namespace illum {
namespace {

// An equal-area test image: brighter towards the image frame's +z and +x, dark (zero) around -z.
Image pattern(int n) {
    Image img(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vector3f d = *env_direction(EnvLayout::Octahedral, {(x + 0.5f) / n, (y + 0.5f) / n});
            float v = std::max(0.0f, 0.3f + d.z) * (1.2f + 0.8f * d.x);
            img(x, y) = Color3(v, v, v);
        }
    return img;
}

TEST(GoniometricLight, PowerIsTheIntegralOfItsIntensity) {
    Image img = pattern(32);
    Transform t = Transform::translate({1, 2, 3}) * Transform::rotate(40, normalize(Vector3f{1, 1, 0}));
    GoniometricLight light(t, Emission(Color3(1, 2, 3)), img);
    // ∫ I dω by uniform sphere sampling (independent of the equal-area map's own texel areas).
    test::MeanAccumulator acc;
    PCG32 rng(5);
    for (int i = 0; i < 400000; ++i) {
        Vector3f w = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        acc.add(light.intensity(w, SampledWavelengths::rgb_mode())[0] * 4 * kPiD);
    }
    double mean_y = img.channel_mean().r;
    EXPECT_NEAR(light.power()[0], 4 * kPiD * mean_y, 1e-5 * 4 * kPiD * mean_y);
    EXPECT_NEAR(light.power()[2], 3 * 4 * kPiD * mean_y, 1e-5 * 12 * kPiD * mean_y);
    EXPECT_NEAR(acc.mean, light.power()[0], 4 * acc.std_error());
    test::expect_photons_match_power(light, 100000, 7, "goniometric");
    test::expect_pdf_le_matches(light, 2000, 9, "goniometric");
    // A delta light: sample_li gives I / r² with probability one, pdf_li is zero.
    LightSampleContext ctx(Point3f{1, 2, 5}, {}, {});
    auto s = light.sample_li(ctx, {0.5f, 0.5f}, SampledWavelengths::rgb_mode());
    ASSERT_TRUE(s);
    EXPECT_EQ(s->pdf.value, 1);
    EXPECT_NEAR(s->biradiance[0], light.intensity({0, 0, 1}, SampledWavelengths::rgb_mode())[0] / 4, 1e-6);
    EXPECT_EQ(light.pdf_li(ctx, s->wi, nullptr).value, 0);
}

// pbrt-v4 swaps y and z: the image's centre (its frame's +z) points along the light's +y.
TEST(GoniometricLight, ImageCentreIsTheLightsPlusY) {
    const int n = 16;
    Image img(n, n);
    for (int y = n / 2 - 1; y <= n / 2; ++y)
        for (int x = n / 2 - 1; x <= n / 2; ++x) img(x, y) = Color3(1.0f);
    GoniometricLight light(Transform(), Emission(Color3(1.0f)), img);
    auto lambda = SampledWavelengths::rgb_mode();
    EXPECT_EQ(light.intensity({0, 1, 0}, lambda)[0], 1);
    EXPECT_EQ(light.intensity({0, 0, 1}, lambda)[0], 0);
    EXPECT_EQ(light.intensity({0, -1, 0}, lambda)[0], 0);
}

// A goniometric light of a constant image renders exactly as the point light of the same intensity.
TEST(GoniometricLight, ConstantImageIsAPointLight) {
    std::string path = test::temp_image(Image(8, 8, Color3(0.5f)), "gonio_constant");
    auto scene = [&](const std::string& light) {
        return fmt::format(R"(
LookAt 0 -3 2  0 0 0  0 0 1
Camera "perspective" "float fov" [50]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
AttributeBegin
  Translate 0.3 0.2 1.5
  {}
AttributeEnd
Material "diffuse" "rgb reflectance" [0.7 0.6 0.5]
Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
Shape "sphere" "float radius" [0.4]
)",
                           light);
    };
    test::RenderSetup s;
    s.spp = 8;
    Image a =
        test::render_pbrt(
            scene(fmt::format(R"(LightSource "goniometric" "string filename" "{}" "rgb I" [2 4 6])", path)),
            s)
            .image;
    Image b = test::render_pbrt(scene(R"(LightSource "point" "rgb I" [1 2 3])"), s).image;
    double diff = 0, ref = 0;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            diff += std::abs(a.data()[i][c] - b.data()[i][c]);
            ref += b.data()[i][c];
        }
    EXPECT_GT(ref, 0);
    EXPECT_LT(diff, 1e-5 * ref);
    std::filesystem::remove(path);
}

TEST(GoniometricLight, FactoryReadsPbrtV4Parameters) {
    std::string path = test::temp_image(pattern(16), "gonio_params");
    SceneDesc d = parse_pbrt_string(fmt::format(R"(WorldBegin
LightSource "goniometric" "string filename" "{}" "rgb I" [1 1 1] "float scale" 2 "float power" 10)",
                                                path),
                                    "<test>", ".");
    Diagnostics diag;
    auto light = make_light(d.lights.at(0), diag);
    ASSERT_TRUE(light);
    EXPECT_TRUE(diag.warnings().empty());
    EXPECT_TRUE(d.lights.at(0).params.unused().empty());
    // pbrt-v4: power 10 divided by 4π mean(Y), then times scale 2: Φ = 20.
    EXPECT_NEAR(light->power()[1], 20, 1e-3);
    std::filesystem::remove(path);
    // A non-square image is not an equal-area map.
    std::string wide = test::temp_image(Image(8, 4, Color3(1.0f)), "gonio_wide");
    SceneDesc w = parse_pbrt_string(
        fmt::format("WorldBegin\nLightSource \"goniometric\" \"string filename\" \"{}\"", wide), "<test>",
        ".");
    EXPECT_THROW(make_light(w.lights.at(0), diag), Error);
    std::filesystem::remove(wide);
}

} // namespace
} // namespace illum
