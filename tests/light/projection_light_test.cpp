// pbrt-v4's projection light: a constant image is a frustum of uniform intensity (irradiance I cos θ / r²
// inside, 0 outside; power I Ω with Ω the pyramid's closed-form solid angle), its power against photons and
// against the integral of its intensity, pdf_le against sample_le, and the image's orientation.
#include <gtest/gtest.h>

#include "illum/light/light_factory.h"
#include "illum/light/projection_light.h"
#include "illum/math/warp.h"
#include "illum/scene/pbrt/parser.h"
#include "image_lights_support.h"
#include "test_support.h"

namespace illum {
namespace {

// The solid angle of the pyramid over [-sx, sx] x [-sy, sy] at distance 1: 4 asin(sin α sin β) with
// tan α = sx, tan β = sy.
double pyramid_solid_angle(double sx, double sy) {
    return 4 * std::asin(sx * sy / std::sqrt((1 + sx * sx) * (1 + sy * sy)));
}

TEST(ProjectionLight, ConstantImageIsAUniformFrustum) {
    const float fov = 50;
    ProjectionLight light(Transform::translate({0, 0, 2}) * Transform::rotate(180, {1, 0, 0}),
                          Image(6, 3, Color3(1, 2, 3)), 1.5f, fov);
    // Wider than tall: the height spans fov.
    double t = std::tan(fov / 2 * kPiD / 180);
    EXPECT_NEAR(light.frustum().sy, t, 1e-6);
    EXPECT_NEAR(light.frustum().sx, 2 * t, 1e-6);
    double omega = pyramid_solid_angle(2 * t, t);
    EXPECT_NEAR(light.power()[0], 1.5 * omega, 1e-5 * omega);
    EXPECT_NEAR(light.power()[2], 4.5 * omega, 1e-5 * omega);
    // Irradiance on the plane z = 0 (2 below the light, which looks down): I cos θ / r² inside the frustum.
    auto lambda = SampledWavelengths::rgb_mode();
    for (float x = -2.5f; x <= 2.5f; x += 0.25f)
        for (float y = -1.5f; y <= 1.5f; y += 0.25f) {
            LightSampleContext ctx(Point3f{x, y, 0}, {}, Normal3f{0, 0, 1});
            auto s = light.sample_li(ctx, {0.5f, 0.5f}, lambda);
            // Light space: +z down, +y flipped by the rotation: the window is |x| <= 2 t·2, |y| <= t·2.
            bool inside = std::abs(x) < 2 * 2 * t * 0.999 && std::abs(y) < 2 * t * 0.999;
            bool outside = std::abs(x) > 2 * 2 * t * 1.001 || std::abs(y) > 2 * t * 1.001;
            if (inside) {
                ASSERT_TRUE(s) << x << " " << y;
                double r2 = x * x + y * y + 4, cos_theta = 2 / std::sqrt(r2);
                EXPECT_NEAR(s->biradiance[0] * std::abs(s->wi.z), 1.5 * cos_theta / r2, 1e-5)
                    << x << " " << y;
            } else if (outside) {
                EXPECT_FALSE(s) << x << " " << y;
            }
        }
    test::expect_photons_match_power(light, 50000, 3, "constant projection");
}

// An image with structure: the power is the integral of the intensity over the sphere; photons and pdf_le
// agree with it.
TEST(ProjectionLight, PowerIsTheIntegralOfItsIntensity) {
    Image img(9, 13);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            img(x, y) = Color3(float((x + 2 * y) % 5), float(x + 1), float(y % 3 == 0 ? 4 : 0.5));
    Transform t = Transform::translate({1, -1, 0.5f}) * Transform::rotate(70, normalize(Vector3f{1, 2, 3}));
    ProjectionLight light(t, img, 0.7f, 75);
    auto lambda = SampledWavelengths::rgb_mode();
    test::MeanAccumulator acc[3];
    PCG32 rng(17);
    for (int i = 0; i < 400000; ++i) {
        Vector3f w = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        Intensity3 v = light.intensity(w, lambda);
        for (int c = 0; c < 3; ++c) acc[c].add(v[c] * 4 * kPiD);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(acc[c].mean, light.power()[c], 4 * acc[c].std_error()) << c;
    test::expect_photons_match_power(light, 100000, 19, "projection");
    test::expect_pdf_le_matches(light, 2000, 23, "projection");
}

// The image's top-left texel lights the light space's upper left (-x, +y): pbrt-v4 projects the image upright
// as a camera would see it.
TEST(ProjectionLight, ImageIsUpright) {
    Image img(4, 4);
    img(0, 0) = Color3(1.0f);
    ProjectionLight light(Transform(), img, 1, 90);
    auto lambda = SampledWavelengths::rgb_mode();
    EXPECT_EQ(light.intensity(normalize(Vector3f{-0.8f, 0.8f, 1}), lambda)[0], 1);
    EXPECT_EQ(light.intensity(normalize(Vector3f{0.8f, 0.8f, 1}), lambda)[0], 0);
    EXPECT_EQ(light.intensity(normalize(Vector3f{-0.8f, -0.8f, 1}), lambda)[0], 0);
    EXPECT_EQ(light.intensity(normalize(Vector3f{-0.8f, 0.8f, -1}), lambda)[0], 0);
}

// Through the parser: irradiance on the receiver under a projection light looking down at it is I / h²,
// nothing when it looks away; pbrt-v4's "power" uses its midpoint sum of lum(L) cos³ θ.
TEST(ProjectionLight, SceneIrradianceAndPower) {
    std::string path = test::temp_image(Image(4, 4, Color3(0.5f, 1, 2)), "projection_constant");
    auto receiver = [&](const std::string& rotate) {
        return test::irradiance_receiver(fmt::format(R"(AttributeBegin
Translate 0 0 2
{}
LightSource "projection" "string filename" "{}" "float fov" [40] "float scale" [3]
AttributeEnd)",
                                                     rotate, path),
                                         "path", 8);
    };
    test::RenderSetup s;
    s.spp = 2;
    Image down = test::render_pbrt(receiver("Rotate 180 1 0 0"), s).image;
    Image up = test::render_pbrt(receiver(""), s).image;
    Color3 i(1.5f, 3, 6); // scale · RGB
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(test::pixel_mean(down, c).mean, i[c] / 4 / kPiD, 1e-4 * i[c]) << c; // E / π, E = I / h²
        EXPECT_EQ(test::pixel_mean(up, c).mean, 0) << c;
    }
    SceneDesc d = parse_pbrt_string(fmt::format("WorldBegin\nLightSource \"projection\" \"string filename\" "
                                                "\"{}\" \"float power\" 5 \"float fov\" 30",
                                                path),
                                    "<test>", ".");
    Diagnostics diag;
    auto light = make_light(d.lights.at(0), diag);
    ASSERT_TRUE(light);
    EXPECT_TRUE(d.lights.at(0).params.unused().empty());
    Image img(4, 4, Color3(0.5f, 1, 2));
    double k = projection_power_normalisation(img, 30);
    // k by hand: plane area 4 t² times the mean of lum · cos³ θ at the 16 centres.
    double t = std::tan(15 * kPiD / 180), sum = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            double a = (2 * (x + 0.5) / 4 - 1) * t, b = (2 * (y + 0.5) / 4 - 1) * t;
            sum += img(0, 0).luminance() * std::pow(1 + a * a + b * b, -1.5);
        }
    EXPECT_NEAR(k, 4 * t * t * sum / 16, 1e-6);
    ProjectionLight expected(Transform(), img, float(5 / k), 30);
    EXPECT_NEAR(light->power()[1], expected.power()[1], 1e-5 * expected.power()[1]);
    std::filesystem::remove(path);
}

} // namespace
} // namespace illum
