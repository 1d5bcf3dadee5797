// Analytic radiometry (DESIGN.md §4.3): the renderer against closed forms. Each check renders a small
// image in which every pixel estimates the same quantity; the tolerance is a multiple of the standard
// error measured over the pixels at a fixed seed, plus a small allowance for float rounding.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

using test::pixel_mean;
using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5; // ~7e-6 two-sided false-alarm rate per check

using test::disk_light;

void expect_radiance(const RenderResult& r, double expected, const char* what, double rel_float = 2e-5) {
    auto g = pixel_mean(r.image, 1);
    std::printf("%-32s expected %.6g, measured %.6g +- %.2g (%+.4f%%)\n", what, expected, g.mean,
                g.standard_error, 100 * (g.mean / expected - 1));
    for (int c = 0; c < 3; ++c) {
        auto m = pixel_mean(r.image, c);
        double tol = kSigmas * m.standard_error + rel_float * expected;
        EXPECT_NEAR(m.mean, expected, tol)
            << what << " channel " << c << " (standard error " << m.standard_error << ")";
    }
    EXPECT_EQ(r.nonfinite_samples, 0u);
}

// E = π L r² / (r² + h²) on the axis of a uniform disk (= π L sin² α).
TEST(Radiometry, DiskIrradianceOnAxis) {
    const double L = 2.0;
    for (auto [r, h] : {std::pair{1.0, 1.0}, std::pair{0.5, 2.0}, std::pair{2.0, 0.5}}) {
        double expected = (1 / kPiD) * kPiD * L * r * r / (r * r + h * h);
        for (const char* integrator : {"direct", "path"}) {
            RenderSetup s;
            s.integrator = integrator;
            s.spp = 16;
            auto res = render_pbrt(test::irradiance_receiver(disk_light(r, h, L), integrator), s);
            expect_radiance(res, expected, fmt::format("{} r={} h={}", integrator, r, h).c_str());
        }
    }
}

// The rule of five: beyond five radii a disk source acts as a point source of intensity I = L π r²
// within a few percent (E_disk / E_point = h² / (r² + h²), 0.96 at h = 5r); near it, it does not.
TEST(Radiometry, RuleOfFive) {
    const double L = 1.0, r = 0.2;
    for (double h : {5 * r, 10 * r, 1 * r}) {
        double intensity = L * kPiD * r * r;
        auto point = render_pbrt(test::irradiance_receiver(fmt::format(
                                     R"(LightSource "point" "point3 from" [0 0 {}] "rgb I" [{} {} {}])", h,
                                     intensity, intensity, intensity)),
                                 {});
        auto disk = render_pbrt(test::irradiance_receiver(disk_light(r, h, L)), {});
        double e_point = point.image.channel_mean().g, e_disk = pixel_mean(disk.image, 1).mean;
        EXPECT_NEAR(e_point, intensity / (h * h) / kPiD, 1e-5 * e_point) << "a point source is exact";
        double ratio = e_disk / e_point, expected_ratio = h * h / (r * r + h * h);
        std::printf("rule of five h=%gr: E_disk/E_point %.5f (closed form %.5f)\n", h / r, ratio,
                    expected_ratio);
        EXPECT_NEAR(ratio, expected_ratio,
                    kSigmas * pixel_mean(disk.image, 1).standard_error / e_point + 1e-4);
        if (h >= 5 * r)
            EXPECT_GT(ratio, 0.96) << "point approximation within 4% beyond five radii";
        else
            EXPECT_LT(ratio, 0.6) << "and far off at one radius";
    }
}

// A sphere of radius R and radiance L seen from distance d on its axis: E = π L (R/d)² (the cone of
// half-angle α with sin α = R/d around the normal). Tests the cone sampling of sphere lights.
TEST(Radiometry, SphereIrradiance) {
    const double L = 3.0;
    for (auto [R, d] : {std::pair{0.5, 2.0}, std::pair{0.01, 3.0}, std::pair{1.0, 1.2}}) {
        std::string world = fmt::format(R"(
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{} {} {}]
  Translate 0 0 {}
  Shape "sphere" "float radius" [{}]
AttributeEnd
)",
                                        L, L, L, d, R);
        for (const char* integrator : {"direct", "path"}) {
            RenderSetup s;
            s.integrator = integrator;
            auto res = render_pbrt(test::irradiance_receiver(world, integrator), s);
            expect_radiance(res, L * (R / d) * (R / d), fmt::format("{} R={} d={}", integrator, R, d).c_str(),
                            1e-4);
        }
    }
}

// Polygon emitter (two triangles): E = L n · Φ with Lambert's irradiance vector
// Φ = ½ Σ Θ_i unit(v_i × v_{i+1}), v_i unit vectors to the vertices and Θ_i the angle between them.
// Near (spherical-triangle sampling) and far (area sampling).
TEST(Radiometry, PolygonIrradiance) {
    const double L = 1.5;
    for (auto [a, h] : {std::pair{0.8, 0.5}, std::pair{0.05, 4.0}, std::pair{3.0, 0.3}}) {
        double vx[4] = {-a, a, a, -a}, vy[4] = {-a / 2, -a / 2, a, a};
        double phi_z = 0;
        for (int i = 0; i < 4; ++i) {
            int j = (i + 1) % 4;
            double p[3] = {vx[i], vy[i], h}, q[3] = {vx[j], vy[j], h};
            double lp = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]),
                   lq = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
            double theta = std::acos((p[0] * q[0] + p[1] * q[1] + p[2] * q[2]) / (lp * lq));
            double c[3] = {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
            double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            phi_z += 0.5 * theta * c[2] / lc;
        }
        double e = L * std::abs(phi_z);
        std::string world =
            fmt::format(R"(
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{L} {L} {L}]
  Shape "trianglemesh" "point3 P" [{x0} {y0} {h} {x1} {y1} {h} {x2} {y2} {h} {x3} {y3} {h}]
      "integer indices" [0 2 1 0 3 2]
AttributeEnd
)",
                        fmt::arg("L", L), fmt::arg("h", h), fmt::arg("x0", vx[0]), fmt::arg("y0", vy[0]),
                        fmt::arg("x1", vx[1]), fmt::arg("y1", vy[1]), fmt::arg("x2", vx[2]),
                        fmt::arg("y2", vy[2]), fmt::arg("x3", vx[3]), fmt::arg("y3", vy[3]));
        for (const char* integrator : {"direct", "path"}) {
            RenderSetup s;
            s.integrator = integrator;
            auto res = render_pbrt(test::irradiance_receiver(world, integrator), s);
            expect_radiance(res, e / kPiD, fmt::format("{} a={} h={}", integrator, a, h).c_str(), 1e-4);
        }
    }
}

// A closed furnace: inside a sphere that emits Le and reflects with Lambertian albedo ρ everywhere,
// radiance is Le / (1 - ρ) in every direction (unbounded depth; Russian roulette keeps it unbiased).
TEST(Radiometry, ClosedFurnace) {
    for (double rho : {0.5, 0.8}) {
        const double le = 0.7;
        std::string scene = test::closed_furnace(rho, le, 24);
        RenderSetup s;
        s.max_depth = -1;
        s.spp = 32;
        auto res = render_pbrt(scene, s);
        expect_radiance(res, le / (1 - rho), fmt::format("furnace rho={}", rho).c_str(), 1e-4);
        // One bounce: emission plus the reflection equation over the whole sphere, Le (1 + ρ), for both
        // integrators (the surfaces' frames differ from the world's, unlike the plane receivers above).
        for (const char* integrator : {"path", "direct"}) {
            s.integrator = integrator;
            s.max_depth = 1;
            s.spp = 8;
            expect_radiance(render_pbrt(scene, s), le * (1 + rho),
                            fmt::format("{} depth 1 rho={}", integrator, rho).c_str(), 1e-4);
        }
    }
}

// Radiance is invariant along a ray: a uniform emitter filling the view looks equally bright from any
// distance (exactly: no sampling is involved at depth 0).
TEST(Radiometry, RadianceInvarianceWithDistance) {
    for (double d : {0.5, 5.0, 500.0}) {
        std::string scene =
            fmt::format(R"(
LookAt 0 0 {d}  0 0 0  0 1 0
Camera "perspective" "float fov" [{fov}]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
Material "diffuse" "rgb reflectance" [0 0 0]
AreaLightSource "diffuse" "rgb L" [0.25 1.5 4]
Shape "trianglemesh" "point3 P" [-1 -1 0 1 -1 0 1 1 0 -1 1 0] "integer indices" [0 1 2 0 2 3]
)",
                        fmt::arg("d", d), fmt::arg("fov", 2 * std::atan(0.8 / d) * 180 / kPiD));
        auto res = render_pbrt(scene, {});
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                Color3 c = res.image(x, y);
                EXPECT_FLOAT_EQ(c.r, 0.25f);
                EXPECT_FLOAT_EQ(c.g, 1.5f);
                EXPECT_FLOAT_EQ(c.b, 4.0f);
            }
    }
}

// A Lambertian plane of albedo ρ under a uniform environment of radiance L reflects ρ L.
TEST(Radiometry, LambertianPlaneUnderConstantEnvironment) {
    const double rho = 0.6;
    std::string scene = fmt::format(R"(
LookAt 0 -3 2  0 0 0  0 0 1
Camera "perspective" "float fov" [10]
Film "rgb" "integer xresolution" [24] "integer yresolution" [24]
WorldBegin
LightSource "infinite" "rgb L" [1 0.5 0.25]
Material "diffuse" "rgb reflectance" [{rho} {rho} {rho}]
Shape "trianglemesh" "point3 P" [-100 -100 0 100 -100 0 100 100 0 -100 100 0] "integer indices" [0 1 2 0 2 3]
)",
                                    fmt::arg("rho", rho));
    for (const char* integrator : {"path", "direct"}) {
        RenderSetup s;
        s.integrator = integrator;
        auto res = render_pbrt(scene, s);
        const double l[3] = {1, 0.5, 0.25};
        for (int c = 0; c < 3; ++c) {
            auto m = pixel_mean(res.image, c);
            EXPECT_NEAR(m.mean, rho * l[c], kSigmas * m.standard_error + 1e-5)
                << integrator << " channel " << c;
        }
    }
}

} // namespace
} // namespace illum
