// pbrt-v4's spherical camera: its rays against the closed forms of the equirectangular and equal-area
// mappings, the round trip direction -> film -> direction, the equal-area property, a uniform environment
// seen as a uniform image, and the errors of bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/camera/spherical_camera.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/render/integrator.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

void expect_near(Vector3f a, Vector3f b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

Vector3f ray_direction(const Camera& cam, Point2f p) {
    std::optional<CameraRay> r = cam.generate_ray(p, {0.5f, 0.5f}, kDLineNm);
    EXPECT_TRUE(r && r->weight == 1);
    return r ? r->ray.d : Vector3f{};
}

TEST(SphericalCamera, EquirectangularRaysAreTheClosedForm) {
    // θ = π v from camera +y, φ = 2π u from +x towards +z (pbrt-v4's direction with y and z swapped).
    const int w = 64, h = 32;
    SphericalCamera cam(Transform(), w, h, SphericalMapping::Equirectangular);
    for (Point2f p : {Point2f{0.5f, 0.5f}, Point2f{16, 16}, Point2f{40.25f, 3.5f}, Point2f{63.5f, 31.5f},
                      Point2f{32, 16}, Point2f{7.75f, 25.125f}}) {
        double theta = kPi * p.y / h, phi = 2 * kPi * p.x / w;
        Vector3f expected{float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                          float(std::sin(theta) * std::sin(phi))};
        expect_near(ray_direction(cam, p), expected, 2e-6f);
    }
    // The named landmarks: the top row looks up, u = 1/4 looks forward (+z), u = 1/2 along -x.
    expect_near(ray_direction(cam, {16, 16}), {0, 0, 1}, 1e-6f);
    expect_near(ray_direction(cam, {32, 16}), {-1, 0, 0}, 1e-6f);
    EXPECT_NEAR(ray_direction(cam, {5, 0}).y, 1, 1e-6f);
}

TEST(SphericalCamera, EqualAreaRaysAreTheClosedForm) {
    // Clarberg's map with pbrt-v4's y/z swap: the centre looks along +y, the corners along -y. On the
    // horizontal centre line (v = 1/2), with a = 2u - 1 and r = |a|: (sign(a) r √(2 - r²), 1 - r², 0).
    const int w = 40, h = 40;
    SphericalCamera cam(Transform(), w, h, SphericalMapping::EqualArea);
    expect_near(ray_direction(cam, {20, 20}), {0, 1, 0}, 1e-6f);
    for (Point2f corner : {Point2f{0, 0}, Point2f{40, 0}, Point2f{0, 40}, Point2f{40, 40}})
        expect_near(ray_direction(cam, corner), {0, -1, 0}, 1e-5f);
    for (float x : {2.0f, 9.0f, 17.5f, 26.0f, 31.25f, 38.0f}) {
        double a = 2.0 * x / w - 1, r = std::abs(a);
        Vector3f expected{float(std::copysign(r * std::sqrt(2 - r * r), a)), float(1 - r * r), 0};
        expect_near(ray_direction(cam, {x, 20}), expected, 2e-6f);
    }
    // The diamond |2u - 1| + |2v - 1| = 1 is the horizon (camera y = 0).
    EXPECT_NEAR(ray_direction(cam, {30, 10}).y, 0, 1e-6f);
}

TEST(SphericalCamera, DirectionToFilmAndBackRoundTrips) {
    PCG32 rng(11);
    for (SphericalMapping m : {SphericalMapping::EqualArea, SphericalMapping::Equirectangular})
        for (int i = 0; i < 2000; ++i) {
            Vector3f d = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
            Point2f uv = spherical_uv(m, d);
            EXPECT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
            expect_near(spherical_direction(m, uv), d, 2e-5f);
            // And film -> direction -> film, away from the seams where uv is not unique.
            Point2f p{0.02f + 0.96f * rng.uniform_float(), 0.02f + 0.96f * rng.uniform_float()};
            Point2f back = spherical_uv(m, spherical_direction(m, p));
            EXPECT_NEAR(back.x, p.x, 2e-5f);
            EXPECT_NEAR(back.y, p.y, 2e-5f);
        }
}

TEST(SphericalCamera, EqualAreaPixelsSubtendEqualSolidAngles) {
    // Uniform directions land uniformly on the film: a chi-square test of 8 x 8 cells (63 degrees of
    // freedom; 120 is beyond its 99.999th percentile), fixed seed.
    constexpr int n = 8, samples = 64000;
    std::vector<int> count(n * n, 0);
    PCG32 rng(5);
    for (int i = 0; i < samples; ++i) {
        Point2f uv = spherical_uv(SphericalMapping::EqualArea,
                                  sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}));
        ++count[std::min(n - 1, int(uv.y * n)) * n + std::min(n - 1, int(uv.x * n))];
    }
    double expected = double(samples) / (n * n), chi2 = 0;
    for (int c : count) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 120);
}

TEST(SphericalCamera, FilmPointsOutsideTheSquareFoldBackAsPbrtV4) {
    // A filter offset past the left edge (u < 0) is the mirror point (-u, 1 - v).
    const int w = 32, h = 32;
    SphericalCamera cam(Transform(), w, h, SphericalMapping::EqualArea);
    expect_near(ray_direction(cam, {-0.5f, 8}),
                spherical_direction(SphericalMapping::EqualArea, {0.5f / w, 1 - 8.0f / h}), 1e-6f);
    expect_near(ray_direction(cam, {9, 32.5f}),
                spherical_direction(SphericalMapping::EqualArea, {1 - 9.0f / w, 2 - 32.5f / h}), 1e-6f);
}

TEST(SphericalCamera, RaysStartAtTheCameraAndTurnWithIt) {
    Transform camera_from_world = Transform::look_at({1, 2, 3}, {1, 2, 10}, {0, 1, 0});
    SphericalCamera cam(camera_from_world.inverse(), 16, 8, SphericalMapping::Equirectangular);
    std::optional<CameraRay> r = cam.generate_ray({4, 4}, {0, 0}, kDLineNm);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->ray.o.x, 1, 1e-5f);
    EXPECT_NEAR(r->ray.o.y, 2, 1e-5f);
    EXPECT_NEAR(r->ray.o.z, 3, 1e-5f);
    // Pixel (4, 4) of 16 x 8 is u = 1/4, v = 1/2: camera +z, the look direction, world +z here.
    EXPECT_NEAR(r->ray.d.z, 1, 1e-5f);
    EXPECT_FALSE(cam.has_importance());
}

std::string spherical_scene(const std::string& camera_params, int w, int h) {
    return "Camera \"spherical\" " + camera_params + "\nFilm \"rgb\" \"integer xresolution\" " +
           std::to_string(w) + " \"integer yresolution\" " + std::to_string(h) +
           "\nSampler \"sobol\" \"integer pixelsamples\" 4\nWorldBegin\n"
           "LightSource \"infinite\" \"rgb L\" [0.25 0.5 0.75]\n";
}

TEST(SphericalCamera, AUniformEnvironmentIsAUniformImage) {
    for (const char* mapping : {"equalarea", "equirectangular"}) {
        RenderResult r =
            test::render_pbrt(spherical_scene(std::string("\"string mapping\" \"") + mapping + "\"", 24, 12));
        for (int y = 0; y < r.image.height(); ++y)
            for (int x = 0; x < r.image.width(); ++x) {
                Color3 c = r.image(x, y);
                EXPECT_NEAR(c.r, 0.25f, 1e-6f) << mapping << " " << x << "," << y;
                EXPECT_NEAR(c.g, 0.5f, 1e-6f);
                EXPECT_NEAR(c.b, 0.75f, 1e-6f);
            }
    }
}

TEST(SphericalCamera, ParsesWithoutWarningsAndIgnoresTheProjectiveParameters) {
    // pbrt-v4 reads screenwindow, frameaspectratio, lensradius and focaldistance for this camera and
    // ignores them: the image is the same as without them.
    std::string plain = spherical_scene("\"string mapping\" \"equirectangular\"", 16, 8);
    std::string extra =
        spherical_scene("\"string mapping\" \"equirectangular\" \"float screenwindow\" "
                        "[-1 1 -0.5 0.5] \"float frameaspectratio\" 2 \"float lensradius\" 0.1 "
                        "\"float focaldistance\" 3",
                        16, 8);
    auto scene = build_scene(parse_pbrt_string(extra, "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_EQ(test::render_pbrt(plain).image, test::render_pbrt(extra).image);
}

TEST(SphericalCamera, BadInputIsAPositionedError) {
    test::expect_error(
        [] {
            build_scene(
                parse_pbrt_string(spherical_scene("\"string mapping\" \"fisheye\"", 8, 8), "s.pbrt", "."));
        },
        "s.pbrt:1:", "unknown spherical camera mapping \"fisheye\"");
    // Light tracing and BDPT need an importance function, which pbrt-v4's spherical camera has not either.
    auto scene = build_scene(parse_pbrt_string(spherical_scene("", 8, 8), "s.pbrt", "."));
    for (const char* integrator : {"bdpt", "lightpath"})
        test::expect_error([&] { make_integrator(integrator, *scene, 5); }, "s.pbrt:1:1",
                           "cannot use camera \"spherical\"");
}

} // namespace
} // namespace illum
