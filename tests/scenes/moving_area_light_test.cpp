// A moving area light (pbrt-v4 rejects it; illum carries the still light's sampling along the motion,
// moving_area_light.h): a small sphere of radiance L moving in a straight line over the shutter, above a
// Lambertian plane z = 0 of albedo ρ. The sphere (radius r, centre c) lies wholly above the plane, so the
// irradiance at a plane point p is exactly that of a uniform sphere, E = π L (r / d)² cos θ with
// d = |c - p| and cos θ = c_z / d, and the plane's radiance is ρ E / π = ρ L r² c_z / d³. A pixel sees the
// time average of that over the shutter and over its footprint on the plane (a box filter of radius 1/2:
// a perspective camera looking straight down maps the pixel's square linearly onto the plane), a closed form
// integrated here by quadrature. The sphere is out of the camera's view and black, so every path of any
// depth sees only the direct light: the path tracer (light sampling and BSDF sampling, weighed by MIS),
// light tracing, BDPT and VCM must all reproduce it.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

constexpr int kWidth = 32;
constexpr double kHalfX = 2, kHalfY = kHalfX / kWidth; // the plane seen: [-2, 2] x [-1/16, 1/16]
constexpr double kCameraZ = 5;
constexpr double kRadius = 0.15, kL = 10, kRho = 0.5;
constexpr double kCentreY = 1, kCentreZ = 1, kFromX = -1.5, kToX = 1.5;

// The scene with `emitter` (an attribute block) above the plane.
std::string scene_around(const std::string& emitter) {
    // pbrt's "fov" spans the shorter image axis (y): tan(fov / 2) = kHalfY / kCameraZ.
    const double fov = 2 * std::atan(kHalfY / kCameraZ) * 180 / kPi;
    return fmt::format(R"(
Film "rgb" "integer xresolution" [{0}] "integer yresolution" [1]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
LookAt 0 0 {1}  0 0 0  0 1 0
Camera "perspective" "float fov" [{2:.9f}]
WorldBegin
AttributeBegin
  Material "diffuse" "rgb reflectance" [{3} {3} {3}]
  Shape "trianglemesh" "point3 P" [-10 -10 0  10 -10 0  10 10 0  -10 10 0] "integer indices" [0 1 2 0 2 3]
AttributeEnd
{4}
)",
                       kWidth, kCameraZ, fov, kRho, emitter);
}

// The sphere emitter; `motion` places it (transform directives before the Shape).
std::string scene_with(const std::string& motion) {
    return scene_around(fmt::format(R"(AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{0} {0} {0}]
  {1}
  Shape "sphere" "float radius" [{2}]
AttributeEnd)",
                                    kL, motion, kRadius));
}

std::string moving_scene() {
    return scene_with(fmt::format("ActiveTransform StartTime\n  Translate {0} {2} {3}\n  ActiveTransform "
                                  "EndTime\n  Translate {1} {2} {3}\n  ActiveTransform All",
                                  kFromX, kToX, kCentreY, kCentreZ));
}
std::string still_scene(double x) {
    return scene_with(fmt::format("Translate {} {} {}", x, kCentreY, kCentreZ));
}

// The plane's radiance at (x, y) lit by the sphere centred at (cx, kCentreY, kCentreZ).
double plane_radiance(double x, double y, double cx, double radius = kRadius) {
    double dx = cx - x, dy = kCentreY - y, dz = kCentreZ;
    double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    return kRho * kL * radius * radius * dz / (d * d * d);
}

// Each pixel's mean over its footprint (midpoint rule, 16 x 4 points) and over the sphere's positions
// `centres` (equally weighted). The image's x runs along the world's -x (pbrt's LookAt is left-handed).
Image closed_form(const std::vector<double>& centres, const std::vector<double>& radii = {}) {
    Image img(kWidth, 1);
    const int nx = 16, ny = 4;
    for (int i = 0; i < kWidth; ++i) {
        double sum = 0;
        for (int a = 0; a < nx; ++a)
            for (int b = 0; b < ny; ++b) {
                double x = -(-kHalfX + 2 * kHalfX * (i + (a + 0.5) / nx) / kWidth);
                double y = -kHalfY + 2 * kHalfY * (b + 0.5) / ny;
                for (std::size_t k = 0; k < centres.size(); ++k)
                    sum += plane_radiance(x, y, centres[k], radii.empty() ? kRadius : radii[k]);
            }
        img.at(i, 0) = Color3(float(sum / (nx * ny * double(centres.size()))));
    }
    return img;
}
// The motion's positions over the shutter [0, 1] (x moves uniformly in time): 4096 midpoints.
std::vector<double> moving_centres() {
    std::vector<double> c;
    const int n = 4096;
    for (int k = 0; k < n; ++k) c.push_back(kFromX + (kToX - kFromX) * (k + 0.5) / n);
    return c;
}

Image render(const std::string& text, const std::string& integrator, int spp, std::uint64_t seed) {
    test::RenderSetup setup;
    setup.integrator = integrator;
    setup.spp = spp;
    setup.seed = seed;
    setup.sampler = "independent";
    RenderResult r = test::render_pbrt(text, setup);
    EXPECT_EQ(r.nonfinite_samples, 0u) << integrator;
    return r.image;
}

// Renders with two seeds against the closed form: the mean over the pixels within 4 σ of the mean of the
// two (plus `bias`, relative), and the per-pixel excess error d = (A - ref)² - (A - B)²/2 (the reference's
// own variance, zero for the exact one) within 4 of its standard errors. Returns σ.
double expect_matches(const std::string& text, const Image& ref, const std::string& integrator, int spp,
                      double bias = 0) {
    Image a = render(text, integrator, spp, 11), b = render(text, integrator, spp, 12);
    test::PixelCheck k = test::pixel_check(a, b, ref, 1);
    double mean_ab = (test::pixel_mean(a, 1).mean + test::pixel_mean(b, 1).mean) / 2;
    double mean_ref = test::pixel_mean(ref, 1).mean;
    std::printf("%-9s mean %.6f (closed form %.6f, sigma %.6f) d %.3g +- %.3g (noise mse %.3g)\n",
                integrator.c_str(), mean_ab, mean_ref, k.mean_sigma, k.d_mean, k.d_se, k.mse_noise);
    EXPECT_NEAR(mean_ab, mean_ref, 4 * k.mean_sigma + bias * mean_ref) << integrator;
    EXPECT_LT(k.d_mean, 4 * k.d_se) << integrator;
    return k.mean_sigma;
}

TEST(MovingAreaLight, RigidMotionBuildsWithoutWarnings) {
    auto scene = build_scene(parse_pbrt_string(moving_scene(), "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_TRUE(scene->has_motion);
    ASSERT_EQ(scene->lights.size(), 1u);
}

// The setup itself: a still sphere at the motion's start is the closed form at that position.
TEST(MovingAreaLight, StillSphereMatchesTheClosedForm) {
    expect_matches(still_scene(kFromX), closed_form({kFromX}), "path", 1024);
}

TEST(MovingAreaLight, PathTracerSeesTheTimeAverage) {
    const Image ref = closed_form(moving_centres());
    double sigma = expect_matches(moving_scene(), ref, "path", 1024);
    // The test can tell: the light left still at its start pose (as before) is many σ away.
    Image start = closed_form({kFromX});
    EXPECT_GT(std::abs(test::pixel_mean(start, 1).mean - test::pixel_mean(ref, 1).mean), 20 * sigma);
}

TEST(MovingAreaLight, EveryIntegratorSeesTheTimeAverage) {
    const Image ref = closed_form(moving_centres());
    expect_matches(moving_scene(), ref, "lightpath", 16384);
    expect_matches(moving_scene(), ref, "bdpt", 1024);
    // VCM's merging blurs the plane's radiance over its shrinking radius, which raises the strip's mean
    // (the radiance is convex across it): +1.3% at 1024 spp and +0.3% at 4096 for the light still at x = 0
    // against the same closed form, so 1% is allowed beside the noise.
    expect_matches(moving_scene(), ref, "vcm", 4096, 0.01);
    expect_matches(moving_scene(), ref, "volpath", 1024);
}

// A one-sided square (a two-triangle mesh: one light per triangle) facing down, moving across and turning
// about x by 60° over the shutter, after `mirror` (a still transform): no closed form, but the path tracer
// (light sampling on the triangles' start pose carried by R(t), BSDF samples finding the moving triangles,
// MIS between them), light tracing and BDPT estimate the same integral, so they agree within their noise.
// Mirrored, the emitting side must stay the same for the sampled start pose and the traced shape.
void expect_integrators_agree_on_turning_square(const std::string& mirror,
                                                const std::string& end_scale = "") {
    const std::string text = scene_around(fmt::format(R"(AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [10 10 10]
  ActiveTransform StartTime
  Translate -1.5 1 1
  ActiveTransform EndTime
  Translate 1.5 1 1
  Rotate 60 1 0 0
  {1}
  ActiveTransform All
  {0}
  Shape "trianglemesh" "point3 P" [-0.15 -0.15 0  -0.15 0.15 0  0.15 0.15 0  0.15 -0.15 0]
    "integer indices" [0 1 2 0 2 3]
AttributeEnd)",
                                                      mirror, end_scale));
    auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_EQ(scene->lights.size(), 2u); // one per triangle
    // The mean over the pixels of two renders (seeds 11, 12) and its σ from their pixels' differences.
    auto mean_of = [&](const std::string& integrator, int spp, double* sigma) {
        Image a = render(text, integrator, spp, 11), b = render(text, integrator, spp, 12);
        *sigma = test::pixel_check(a, b, a, 1).mean_sigma;
        return (test::pixel_mean(a, 1).mean + test::pixel_mean(b, 1).mean) / 2;
    };
    double s_path = 0;
    const double path = mean_of("path", 2048, &s_path);
    EXPECT_GT(path, 100 * s_path); // the square faces the plane
    for (auto [integrator, spp] : {std::pair<const char*, int>{"lightpath", 16384}, {"bdpt", 1024}}) {
        double s = 0;
        double m = mean_of(integrator, spp, &s);
        std::printf("%s%s %-9s mean %.6f +- %.6f (path %.6f +- %.6f)\n", mirror.c_str(), end_scale.c_str(),
                    integrator, m, s, path, s_path);
        EXPECT_NEAR(m, path, 4 * std::sqrt(s * s + s_path * s_path)) << integrator;
    }
}

TEST(MovingAreaLight, ATurningMeshEmitterIsSeenAlikeByEveryIntegrator) {
    expect_integrators_agree_on_turning_square("");
}

TEST(MovingAreaLight, AMirroredTurningMeshEmitterIsSeenAlikeByEveryIntegrator) {
    expect_integrators_agree_on_turning_square("Scale -1 1 1");
}

// A motion that changes the light's size is exact too: the sphere moving as above while its radius grows
// linearly from r to 2r (pbrt-v4 interpolates the scale factor linearly; so does Embree here), against the
// closed form averaged over the motion, with the densities carried by the Jacobians of R(t).
TEST(MovingAreaLight, AGrowingSphereIsTheTimeAverage) {
    const std::string text =
        scene_with(fmt::format("ActiveTransform StartTime\n  Translate {0} {2} {3}\n  "
                               "ActiveTransform EndTime\n  Translate {1} {2} {3}\n  Scale 2 "
                               "2 2\n  ActiveTransform All",
                               kFromX, kToX, kCentreY, kCentreZ));
    auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    std::vector<double> centres = moving_centres(), radii;
    for (std::size_t k = 0; k < centres.size(); ++k)
        radii.push_back(kRadius * (1 + (k + 0.5) / double(centres.size())));
    const Image ref = closed_form(centres, radii);
    double sigma = expect_matches(text, ref, "path", 1024);
    // The sphere's size at the start (as if the densities were the start pose's) is many σ away.
    EXPECT_GT(std::abs(test::pixel_mean(closed_form(centres), 1).mean - test::pixel_mean(ref, 1).mean),
              20 * sigma);
    expect_matches(text, ref, "lightpath", 16384);
    expect_matches(text, ref, "bdpt", 1024);
}

// A square stretched to twice its width along x while it moves and turns: no closed form, the integrators
// agree (light tracing's photons carry the area and direction Jacobians, the path tracer's light samples the
// solid-angle one).
TEST(MovingAreaLight, AStretchingMeshEmitterIsSeenAlikeByEveryIntegrator) {
    expect_integrators_agree_on_turning_square("", "Scale 2 1 1");
}

// "power" sets the radiance from the area, which a motion that changes the size changes: the start pose's is
// used, with a warning at the shape.
TEST(MovingAreaLight, PowerOfAResizingLightWarns) {
    std::string text = scene_with("ActiveTransform EndTime\n  Scale 2 2 2\n  ActiveTransform All");
    auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    std::string with_power = text;
    with_power.replace(with_power.find("\"rgb L\""), 0, "\"float power\" [3] ");
    scene = build_scene(parse_pbrt_string(with_power, "<test>", "."));
    ASSERT_EQ(scene->warnings.size(), 1u);
    EXPECT_NE(scene->warnings[0].find("<test>:17:3: a moving area light whose motion changes its size"),
              std::string::npos)
        << scene->warnings[0];
}

} // namespace
} // namespace illum
