// Emitters: photon emission (sample_le) against each light's analytic power, the spot falloff, and the
// scene-level light types against closed-form irradiance.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include "illum/geometry/disk.h"
#include "illum/image/image_io.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/directional_light.h"
#include "illum/light/image_environment_light.h"
#include "illum/light/point_light.h"
#include "illum/light/spot_light.h"
#include "illum/light/uniform_environment_light.h"
#include "illum/math/rng.h"
#include "math/stat_util.h"
#include "test_support.h"

namespace illum {
namespace {

using test::MeanAccumulator;

// The power estimated from n photons of sample_le, per channel, with its standard error.
struct PowerEstimate {
    MeanAccumulator acc[3];
};
PowerEstimate estimate_power(const Light& light, int n, std::uint64_t seed) {
    PCG32 rng(seed);
    PowerEstimate e;
    for (int i = 0; i < n; ++i) {
        Point2f u1{rng.uniform_float(), rng.uniform_float()}, u2{rng.uniform_float(), rng.uniform_float()};
        auto s = light.sample_le(u1, u2, SampledWavelengths::rgb_mode());
        for (int c = 0; c < 3; ++c) e.acc[c].add(s ? double(s->flux[c]) : 0.0);
        if (s) {
            // The flux is the documented ratio of the sample's own quantities.
            EXPECT_TRUE(s->flux.is_finite());
            EXPECT_NEAR(length(s->ray.d), 1.0f, 1e-4f);
        }
    }
    return e;
}

// Within 3 standard errors (plus float rounding for the zero-variance estimators).
void expect_power(const PowerEstimate& e, Color3 analytic, const char* what) {
    for (int c = 0; c < 3; ++c) {
        double tol = 3 * e.acc[c].std_error() + 1e-4 * std::abs(analytic[c]);
        EXPECT_NEAR(e.acc[c].mean, analytic[c], tol) << what << " channel " << c;
    }
}

const Bounds3f kScene{{-1, -2, 0}, {3, 1, 2}};

TEST(SampleLe, DiffuseAreaLightOneAndTwoSided) {
    const float r = 0.5f;
    DiskShape disk(Transform::translate({0, 0, 1}), 0, r, 0, false);
    Radiance3 l(1, 2, 3);
    double area = kPiD * r * r; // from the disk's radius, not from the shape
    for (bool two : {false, true}) {
        DiffuseAreaLight light(&disk, l, two);
        Color3 phi = l.rgb() * float(kPiD * area * (two ? 2 : 1));
        expect_power(estimate_power(light, 20000, 1), phi, two ? "two-sided disk" : "one-sided disk");
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(light.power()[c], phi[c], 1e-4 * phi[c]);
        // Photons leave from the emitting side.
        PCG32 rng(7);
        for (int i = 0; i < 1000; ++i) {
            auto s =
                light.sample_le({rng.uniform_float(), rng.uniform_float()},
                                {rng.uniform_float(), rng.uniform_float()}, SampledWavelengths::rgb_mode());
            ASSERT_TRUE(s);
            if (!two) {
                EXPECT_GT(dot(s->ray.d, s->n), 0);
            }
            EXPECT_NEAR(s->pdf_dir.value, std::abs(dot(s->ray.d, s->n)) / kPi * (two ? 0.5f : 1.0f), 1e-4f);
        }
    }
}

TEST(SampleLe, PointLight) {
    PointLight light({1, 2, 3}, Intensity3(0.5f, 1, 2));
    expect_power(estimate_power(light, 1000, 2), Color3(0.5f, 1, 2) * float(4 * kPiD), "point");
}

// The spot light's power Φ = 2π I [(1 - cos θs) + (cos θs - cos θe) / 2], checked against a direct
// quadrature of the falloff over the sphere and against photon emission.
TEST(SampleLe, SpotLight) {
    for (auto [cone, delta] : {std::pair{30.0f, 5.0f}, std::pair{60.0f, 40.0f}, std::pair{10.0f, 0.0f}}) {
        float ce = std::cos(cone * kPi / 180), cs = std::cos((cone - delta) * kPi / 180);
        SpotLight light({0, 0, 0}, normalize(Vector3f{1, 1, 0}), Intensity3(1, 2, 4), cone * kPi / 180,
                        delta * kPi / 180);
        double closed = 2 * kPiD * ((1 - cs) + (cs - ce) / 2);
        // Quadrature over cos θ (the falloff depends on it only).
        double quad = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) quad += light.falloff(-1 + 2 * (i + 0.5f) / n) * (2.0 / n) * 2 * kPiD;
        EXPECT_NEAR(quad, closed, (delta > 0 ? 1e-4 : 1e-3) * closed) << cone << " " << delta;
        EXPECT_NEAR(light.power()[0], closed, 1e-4 * closed);
        auto e = estimate_power(light, 40000, 3);
        expect_power(e, Color3(1, 2, 4) * float(closed), fmt::format("spot {} {}", cone, delta).c_str());
        if (delta > 0) {
            EXPECT_GT(e.acc[0].std_error(), 0) << "the estimator should vary when the falloff is smooth";
        }
    }
    // Falloff: 1 inside the inner cone, 0 outside, 1/2 halfway in cos θ.
    SpotLight s({0, 0, 0}, {0, 0, 1}, Intensity3(1.0f), 0.5f, 0.2f);
    EXPECT_EQ(s.falloff(1), 1);
    EXPECT_EQ(s.falloff(std::cos(0.6f)), 0);
    EXPECT_NEAR(s.falloff(0.5f * (std::cos(0.5f) + std::cos(0.3f))), 0.5f, 1e-5f);
}

TEST(SampleLe, DirectionalLight) {
    DirectionalLight light(normalize(Vector3f{1, -1, 2}), Irradiance3(1, 2, 3));
    light.preprocess(kScene);
    Point3f c;
    float r;
    kScene.bounding_sphere(&c, &r);
    expect_power(estimate_power(light, 1000, 4), Color3(1, 2, 3) * float(kPiD * r * r), "directional");
    // Every photon starts outside the scene's sphere and travels along -w.
    PCG32 rng(5);
    for (int i = 0; i < 100; ++i) {
        auto s = light.sample_le({rng.uniform_float(), rng.uniform_float()}, {0.5f, 0.5f},
                                 SampledWavelengths::rgb_mode());
        ASSERT_TRUE(s);
        EXPECT_NEAR(dot(s->ray.d, -light.direction()), 1, 1e-5);
        EXPECT_GE(distance(s->ray.o, c), r * 0.999f);
    }
}

TEST(SampleLe, UniformEnvironment) {
    UniformEnvironmentLight light(Radiance3(0.5f, 1, 2));
    light.preprocess(kScene);
    Point3f c;
    float r;
    kScene.bounding_sphere(&c, &r);
    Color3 phi = Color3(0.5f, 1, 2) * float(4 * kPiD * kPiD * r * r);
    expect_power(estimate_power(light, 1000, 6), phi, "uniform environment");
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(light.power()[k], phi[k], 1e-4 * phi[k]);
}

// A latitude-longitude test image: a smooth sky with a bright sun-like spot.
Image sun_sky(int w, int h, float sun_theta, float sun_phi, float sun_radius, float sun_value) {
    Image img(w, h);
    Vector3f sun = spherical_direction(std::sin(sun_theta), std::cos(sun_theta), sun_phi);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float theta = kPi * (y + 0.5f) / h, phi = 2 * kPi * (x + 0.5f) / w;
            Vector3f d = spherical_direction(std::sin(theta), std::cos(theta), phi);
            float sky = 0.2f + 0.8f * std::max(0.0f, d.z);
            Color3 c(sky * 0.6f, sky * 0.8f, sky);
            if (safe_acos(dot(d, sun)) < sun_radius)
                c += Color3(sun_value, sun_value * 0.9f, sun_value * 0.7f);
            img(x, y) = c;
        }
    return img;
}

TEST(SampleLe, ImageEnvironment) {
    const int w = 64, h = 32;
    Image img = sun_sky(w, h, 0.6f, 1.0f, 0.15f, 200.0f);
    // ∫ L dω by the latitude-longitude texel areas Δφ (cos θ0 - cos θ1), computed here independently.
    double integral[3] = {0, 0, 0};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sa = 2 * kPiD / w * (std::cos(kPiD * y / h) - std::cos(kPiD * (y + 1) / h));
            for (int c = 0; c < 3; ++c) integral[c] += img(x, y)[c] * sa;
        }
    ImageEnvironmentLight light(EnvironmentMap(img, EnvLayout::LatLong), Transform::rotate(30, {1, 0, 0}),
                                2.0f);
    light.preprocess(kScene);
    Point3f c;
    float r;
    kScene.bounding_sphere(&c, &r);
    Color3 phi;
    for (int k = 0; k < 3; ++k) phi[k] = float(2 * integral[k] * kPiD * r * r);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(light.power()[k], phi[k], 1e-4 * phi[k]);
    // The bilinearly filtered map integrates to the texel sum only approximately: allow 1% for that.
    auto e = estimate_power(light, 200000, 8);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(e.acc[k].mean, phi[k], 3 * e.acc[k].std_error() + 0.01 * phi[k]) << "channel " << k;
}

// ---- scene-level lights through the pbrt-v4 parser and the light factory ----

// The receiver (test_support.h) rendered with the path tracer at 8 x 8: every pixel shows E / π.
std::string receiver(const std::string& world) { return test::irradiance_receiver(world, "path", 8); }

void expect_mean(const RenderResult& r, double expected, const std::string& what, double rel = 1e-4) {
    for (int c = 0; c < 3; ++c) {
        auto m = test::pixel_mean(r.image, c);
        EXPECT_NEAR(m.mean, expected, 4.5 * m.standard_error + rel * expected) << what << " channel " << c;
    }
}

TEST(SceneLights, DistantSpotPoint) {
    test::RenderSetup s;
    s.spp = 4;
    // Irradiance L on a perpendicular surface; light from `from` towards `to`.
    expect_mean(
        test::render_pbrt(
            receiver(R"(LightSource "distant" "point3 from" [0 0 1] "point3 to" [0 0 0] "rgb L" [2 2 2])"),
            s),
        2 / kPiD, "distant overhead");
    expect_mean(
        test::render_pbrt(
            receiver(
                R"(LightSource "distant" "point3 from" [1 0 1] "point3 to" [0 0 0] "rgb L" [2 2 2] "float scale" 3)"),
            s),
        6 * std::cos(kPiD / 4) / kPiD, "distant at 45 degrees");
    {
        // "illuminance" multiplies the RGB as pbrt-v4 does (its photometric normalisation leaves an RGB
        // multiplier as it is): E = 5 (1, 2, 3) on a perpendicular surface, so the white plane shows
        // E/π, of luminance 5 lum(1, 2, 3) / π.
        auto r = test::render_pbrt(
            receiver(
                R"(LightSource "distant" "point3 from" [0 0 1] "point3 to" [0 0 0] "rgb L" [1 2 3] "float illuminance" 5)"),
            s);
        Color3 m(float(test::pixel_mean(r.image, 0).mean), float(test::pixel_mean(r.image, 1).mean),
                 float(test::pixel_mean(r.image, 2).mean));
        EXPECT_NEAR(m.luminance(), 5 * Color3(1, 2, 3).luminance() / kPi, 1e-3);
        EXPECT_NEAR(m[1] / m[0], 2, 1e-4);
    }
    // Spot on its axis: I / h²; outside its cone: nothing.
    expect_mean(
        test::render_pbrt(
            receiver(R"(LightSource "spot" "point3 from" [0 0 2] "point3 to" [0 0 0] "rgb I" [8 8 8])"), s),
        2 / kPiD, "spot on axis");
    expect_mean(
        test::render_pbrt(
            receiver(R"(LightSource "spot" "point3 from" [1 0 1] "point3 to" [2 0 0] "rgb I" [8 8 8])"), s),
        0, "spot pointing away");
    // Spot given by power: Φ = 2π I ((1 - cos 25°) + (cos 25° - cos 30°) / 2).
    double k =
        2 * kPiD *
        ((1 - std::cos(25 * kPiD / 180)) + (std::cos(25 * kPiD / 180) - std::cos(30 * kPiD / 180)) / 2);
    expect_mean(
        test::render_pbrt(
            receiver(R"(LightSource "spot" "point3 from" [0 0 1] "point3 to" [0 0 0] "float power" 10)"), s),
        10 / k / kPiD, "spot by power", 1e-3);
}

// An environment map file of constant radiance: a white plane sees radiance ρ L = L on every layout the
// factory detects (2:1 latlong, 1:1 octahedral), rotated or not; "illuminance" normalises E(up).
TEST(SceneLights, InfiniteFromFile) {
    auto dir = std::filesystem::temp_directory_path() / "illum_light_test";
    std::filesystem::create_directories(dir);
    write_image(Image(32, 16, Color3(0.5f, 1, 1.5f)), (dir / "const_ll.pfm").string());
    write_image(Image(16, 16, Color3(0.5f, 1, 1.5f)), (dir / "const_oct.exr").string());
    test::RenderSetup s;
    s.spp = 16;
    for (const char* f : {"const_ll.pfm", "const_oct.exr"}) {
        std::string path = (dir / f).string();
        auto r = test::render_pbrt(receiver(fmt::format(R"(Rotate 40 1 1 0
LightSource "infinite" "string filename" "{}" "float scale" 2)",
                                                        path)),
                                   s);
        for (int c = 0; c < 3; ++c) {
            auto m = test::pixel_mean(r.image, c);
            double expected = 2 * 0.5 * (c + 1);
            EXPECT_NEAR(m.mean, expected, 4.5 * m.standard_error + 2e-3 * expected) << f << " channel " << c;
        }
        auto r2 = test::render_pbrt(
            receiver(
                fmt::format(R"(LightSource "infinite" "string filename" "{}" "float illuminance" 3)", path)),
            s);
        // E(up) = 3 in luminance, so the plane's luminance is 3 / π.
        double lum = 0;
        for (int c = 0; c < 3; ++c)
            lum += test::pixel_mean(r2.image, c).mean * Color3(c == 0, c == 1, c == 2).luminance();
        EXPECT_NEAR(lum, 3 / kPiD, 0.01 * 3 / kPiD) << f;
    }
    // Bad input: a missing file, an LDR file, a wrong aspect ratio: errors, not crashes.
    write_image(Image(30, 16, Color3(1.0f)), (dir / "bad_aspect.pfm").string());
    write_image(Image(16, 16, Color3(1.0f)), (dir / "ldr.png").string());
    for (const char* f : {"missing.exr", "ldr.png", "bad_aspect.pfm"}) {
        std::string text =
            receiver(fmt::format(R"(LightSource "infinite" "string filename" "{}")", (dir / f).string()));
        EXPECT_THROW(test::render_pbrt(text, s), Error) << f;
    }
    // A black map: no light, no NaN.
    write_image(Image(32, 16, Color3(0.0f)), (dir / "black.pfm").string());
    auto rb = test::render_pbrt(receiver(fmt::format(R"(LightSource "infinite" "string filename" "{}")",
                                                     (dir / "black.pfm").string())),
                                s);
    EXPECT_EQ(rb.nonfinite_samples, 0u);
    EXPECT_EQ(rb.image.channel_mean()[0], 0.0f);
}

// A spot light's illuminated_interval() (the stretch of a line inside its cone, where equiangular sampling in
// media samples) against brute force: along random lines, every point the light reaches (falloff > 0) lies
// inside the interval, and the interval holds no point outside the slightly widened cone. Cones narrow and
// wide, lines through the apex's neighbourhood and far off, in both directions along the axis.
TEST(SpotLight, IlluminatedIntervalIsTheConeAlongTheLine) {
    PCG32 rng(5);
    int lost = 0, extra = 0, lines = 0;
    for (float cone_deg : {5.0f, 15.0f, 30.0f, 60.0f, 89.0f}) {
        Vector3f axis = normalize(Vector3f(0.3f, -1, 0.2f));
        Point3f c(0.75f, 1.8f, 0.3f);
        SpotLight spot(c, axis, Emission(Color3(1.0f)), cone_deg * kPi / 180, 0.05f);
        for (int i = 0; i < 2000; ++i, ++lines) {
            Point3f o = c + Vector3f{4 * rng.uniform_float() - 2, 4 * rng.uniform_float() - 2,
                                     4 * rng.uniform_float() - 2};
            Vector3f d = normalize(sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}));
            float t0 = 0, t1 = 6;
            bool any = spot.illuminated_interval(o, d, &t0, &t1);
            for (int k = 0; k <= 600; ++k) {
                float t = 0.01f * k;
                Vector3f w = normalize(o + d * t - c);
                bool lit = spot.falloff(dot(w, axis)) > 0;
                bool inside = any && t >= t0 && t <= t1;
                lost += lit && !inside;
                // Outside the cone widened by 0.01 rad (the interval's own margin is 1e-3 rad).
                extra += inside && dot(w, axis) < std::cos(cone_deg * kPi / 180 + 0.01f);
            }
        }
    }
    EXPECT_EQ(lost, 0) << "of " << lines << " lines";
    EXPECT_EQ(extra, 0);
}

} // namespace
} // namespace illum
