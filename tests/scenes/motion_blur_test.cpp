// Motion blur end to end (pbrt-v4's ActiveTransform, TransformTimes, shutteropen/shutterclose): a black
// sphere moving across a white sky seen by an orthographic camera, one row of pixels, a pixel filter so
// narrow that each sample looks along its pixel's centre. A pixel then sees the sky except while the
// sphere covers its centre, so its value is 1 minus the fraction of the shutter interval during which the
// sphere does: a closed form. The same picture must come from a camera moving the other way, from a moving
// object instance, and from every thread count; a moving scene seen over an instant is the still scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "test_support.h"

namespace illum {
namespace {

constexpr int kPixels = 32;
constexpr double kRadius = 0.5, kFrom = -2, kTo = 2; // the sphere's centre moves along x from kFrom to kTo
constexpr double kWindow = 4;                        // the screen spans x in [-4, 4]: pixels 0.25 wide

// The options block: an orthographic camera with the given transform directives (before Camera) and
// shutter, looking along +z at the plane z = 0.
std::string options(const std::string& camera_transform, const std::string& shutter = "") {
    return fmt::format(R"(
Film "rgb" "integer xresolution" [{0}] "integer yresolution" [1]
PixelFilter "box" "float xradius" [0.0001] "float yradius" [0.0001]
Sampler "sobol"
{1}
Camera "orthographic" "float screenwindow" [-{2} {2} -0.125 0.125] {3}
WorldBegin
LightSource "infinite" "rgb L" [1 1 1]
Material "diffuse" "rgb reflectance" [0 0 0]
)",
                       kPixels, camera_transform, kWindow, shutter);
}

const char* kStillCamera = "LookAt 0 0 -10  0 0 0  0 1 0";

// A translation along x from `from` at the start time to `to` at the end time, then back to both.
std::string translation_motion(double from, double to) {
    return fmt::format(R"(ActiveTransform StartTime
  Translate {} 0 0
  ActiveTransform EndTime
  Translate {} 0 0
  ActiveTransform All)",
                       from, to);
}

// The sphere of radius kRadius moving from `from` to `to`.
std::string moving_sphere(double from, double to) {
    return translation_motion(from, to) + fmt::format("\n  Shape \"sphere\" \"float radius\" [{}]", kRadius);
}

// The sphere moving from kFrom to kTo over TransformTimes 0 1 (the default).
std::string moving_sphere_scene(const std::string& shutter = "") {
    return options(kStillCamera, shutter) + "\nAttributeBegin\n  " + moving_sphere(kFrom, kTo) +
           "\nAttributeEnd\n";
}

Image render(const std::string& text, int spp, int threads = 0) {
    test::RenderSetup setup;
    setup.spp = spp;
    setup.max_depth = 1;
    setup.threads = threads;
    RenderResult r = test::render_pbrt(text, setup);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    return r.image;
}

// The pixel centres' x and the fraction of the shutter [0, 1] during which the sphere covers x:
// |kFrom + (kTo - kFrom) t - x| < r.
double pixel_x(int i) { return -kWindow + 2 * kWindow * (i + 0.5) / kPixels; }
double covered_fraction(double x) {
    double t0 = (x - kRadius - kFrom) / (kTo - kFrom), t1 = (x + kRadius - kFrom) / (kTo - kFrom);
    return std::max(0.0, std::min(t1, 1.0) - std::max(t0, 0.0));
}

TEST(MotionBlur, ParsesWithoutWarnings) {
    auto scene = build_scene(parse_pbrt_string(moving_sphere_scene(), "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_TRUE(scene->has_motion);
}

TEST(MotionBlur, CoverageIsTheFractionOfTheShutterInterval) {
    const int spp = 4096;
    Image img = render(moving_sphere_scene(), spp);
    ASSERT_EQ(img.width(), kPixels);
    int partly_covered = 0;
    for (int i = 0; i < kPixels; ++i) {
        double f = covered_fraction(pixel_x(i)), expected = 1 - f;
        // Each sample sees the sky or not: a Bernoulli variable of mean 1 - f (the Sobol' times do better
        // than independent ones; 4 binomial standard errors plus float rounding).
        double sigma = std::sqrt(f * (1 - f) / spp);
        EXPECT_NEAR(img.at(i, 0).g, expected, 4 * sigma + 1e-5) << "pixel " << i << " at x " << pixel_x(i);
        partly_covered += f > 0 && f < 1;
    }
    EXPECT_GE(partly_covered, 20); // the blur spans 4 + 2r = 5 units: 20 pixels
}

TEST(MotionBlur, AShutterInsideTheMotionSeesItsPartOfTheMotion) {
    // shutter [0.25, 0.75]: the sphere sweeps x from -1 to 1 meanwhile. The exposure is 0.5 s, so the sky
    // gives 0.5 (the sensor's imaging ratio).
    const int spp = 4096;
    Image img = render(moving_sphere_scene(R"("float shutteropen" [0.25] "float shutterclose" [0.75])"), spp);
    for (int i = 0; i < kPixels; ++i) {
        double x = pixel_x(i);
        // Covered while |-1 + 2 s - x| < r, s in [0, 1] the fraction of the shutter.
        double s0 = (x - kRadius + 1) / 2, s1 = (x + kRadius + 1) / 2;
        double f = std::max(0.0, std::min(s1, 1.0) - std::max(s0, 0.0));
        double sigma = std::sqrt(f * (1 - f) / spp);
        EXPECT_NEAR(img.at(i, 0).g, 0.5 * (1 - f), 0.5 * (4 * sigma) + 1e-5) << "pixel " << i;
    }
}

TEST(MotionBlur, AMovingCameraSeesTheSceneMovingTheOtherWay) {
    // The camera moves from x = -kFrom to -kTo over the still sphere at 0: relative to the camera, the
    // sphere makes the same motion. Both scenes draw the same time per sample, so the images agree to
    // within a sample flipped by rounding at the sphere's edge.
    const int spp = 1024;
    Image moving_sphere = render(moving_sphere_scene(), spp);
    std::string camera = fmt::format(R"(ActiveTransform StartTime
LookAt {0} 0 -10  {0} 0 0  0 1 0
ActiveTransform EndTime
LookAt {1} 0 -10  {1} 0 0  0 1 0
ActiveTransform All)",
                                     -kFrom, -kTo);
    Image moving_camera =
        render(options(camera) + fmt::format("Shape \"sphere\" \"float radius\" [{}]\n", kRadius), spp);
    for (int i = 0; i < kPixels; ++i)
        EXPECT_NEAR(moving_camera.at(i, 0).g, moving_sphere.at(i, 0).g, 2.0 / spp) << "pixel " << i;
}

TEST(MotionBlur, AMovingInstanceIsAMovingShape) {
    const int spp = 1024;
    Image shape = render(moving_sphere_scene(), spp);
    Image instance = render(options(kStillCamera) + fmt::format(R"(
ObjectBegin "ball"
  Shape "sphere" "float radius" [{}]
ObjectEnd
AttributeBegin
  {}
  ObjectInstance "ball"
AttributeEnd
)",
                                                                kRadius, translation_motion(kFrom, kTo)),
                            spp);
    for (int i = 0; i < kPixels; ++i)
        EXPECT_NEAR(instance.at(i, 0).g, shape.at(i, 0).g, 2.0 / spp) << "pixel " << i;
}

TEST(MotionBlur, AnInstantOfTheMotionIsTheStillScene) {
    // A shutter of 1e-4 s at t = 0.5: the sphere stands at x = 0 (it moves 4e-4, and no pixel centre lies
    // that close to its edge). Both scenes have the same exposure, hence imaging ratio.
    const char* shutter = R"("float shutteropen" [0.5] "float shutterclose" [0.5001])";
    Image moving = render(moving_sphere_scene(shutter), 64);
    Image still = render(options(kStillCamera, shutter) +
                             fmt::format("Shape \"sphere\" \"float radius\" [{}]\n", kRadius),
                         64);
    for (int i = 0; i < kPixels; ++i) {
        EXPECT_NEAR(moving.at(i, 0).g, still.at(i, 0).g, 1e-9) << "pixel " << i;
        double exposure = double(0.5001f - 0.5f); // as the sensor computes it
        EXPECT_NEAR(still.at(i, 0).g, std::abs(pixel_x(i)) < kRadius ? 0.0 : exposure, 1e-10)
            << "pixel " << i;
    }
    // Equal start and end transforms are no motion at all: the scene is the still one, sample for sample.
    std::string no_motion = options(kStillCamera) + R"(
ActiveTransform EndTime
Translate 0 0 0
ActiveTransform All
Shape "sphere" "float radius" [0.5]
)";
    auto scene = build_scene(parse_pbrt_string(no_motion, "<test>", "."));
    EXPECT_FALSE(scene->has_motion);
}

TEST(MotionBlur, DeterministicAcrossThreadCounts) {
    std::string text = moving_sphere_scene();
    Image one = render(text, 64, 1), two = render(text, 64, 2), four = render(text, 64, 4);
    for (int i = 0; i < kPixels; ++i) {
        EXPECT_EQ(one.at(i, 0).g, two.at(i, 0).g) << "pixel " << i;
        EXPECT_EQ(one.at(i, 0).g, four.at(i, 0).g) << "pixel " << i;
    }
}

// A small emitter seen by a perspective camera that moves sideways: every integrator must see it smeared
// over the camera's motion. Light tracing, BDPT and VCM reach the camera by connections (sample_wi, pdf_we),
// which must see the camera where it is at the path's time, not at its start pose (that gave a sharp
// square at the start position). Compared with the path tracer on the streak's columns: its total, its
// centroid and its extent.
TEST(MotionBlur, EveryIntegratorSeesAMovingCameraAtThePathsTime) {
    const std::string scene = R"(
Film "rgb" "integer xresolution" [64] "integer yresolution" [16]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
Sampler "independent"
ActiveTransform StartTime
LookAt -1 0 -5  -1 0 0  0 1 0
ActiveTransform EndTime
LookAt 1 0 -5  1 0 0  0 1 0
ActiveTransform All
Camera "perspective" "float fov" [30]
WorldBegin
Material "diffuse" "rgb reflectance" [0 0 0]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [4 4 4]
  Shape "trianglemesh" "point3 P" [-0.15 -0.15 0  -0.15 0.15 0  0.15 0.15 0  0.15 -0.15 0]
    "integer indices" [0 1 2 0 2 3]
AttributeEnd
)";
    struct Profile {
        double total = 0, centroid = 0;
        int first = -1, last = -1;
    };
    auto profile = [](const Image& img) {
        std::vector<double> col(std::size_t(img.width()), 0.0);
        double peak = 0;
        Profile p;
        for (int x = 0; x < img.width(); ++x) {
            for (int y = 0; y < img.height(); ++y) col[std::size_t(x)] += img.at(x, y).g;
            p.total += col[std::size_t(x)];
            p.centroid += x * col[std::size_t(x)];
            peak = std::max(peak, col[std::size_t(x)]);
        }
        p.centroid /= p.total;
        for (int x = 0; x < img.width(); ++x)
            if (col[std::size_t(x)] > 0.2 * peak) {
                if (p.first < 0) p.first = x;
                p.last = x;
            }
        return p;
    };
    const int kSpp = 1024;
    auto render_with = [&](const std::string& integrator) {
        test::RenderSetup setup;
        setup.integrator = integrator;
        setup.spp = kSpp;
        setup.sampler = "independent";
        setup.seed = 5;
        RenderResult r = test::render_pbrt(scene, setup);
        EXPECT_EQ(r.nonfinite_samples, 0u) << integrator;
        return profile(r.image);
    };
    Profile path = render_with("path");
    // The square (1 pixel wide here) moves 2 units across the view: about 12 columns.
    EXPECT_GE(path.last - path.first, 9);
    // The path tracer's total is L times a sum of Bernoulli fractions (a sample sees the square or not):
    // variance L Σ/spp. Two such estimates differ by 4.5 standard errors of their difference at most.
    const double sigma = std::sqrt(4.0 * path.total / kSpp), tolerance = 4.5 * std::sqrt(2.0) * sigma;
    for (const char* integrator : {"lightpath", "bdpt", "vcm"}) {
        Profile p = render_with(integrator);
        std::printf("%-9s total %.4f (path %.4f) centroid %.2f (%.2f) columns %d-%d (%d-%d)\n", integrator,
                    p.total, path.total, p.centroid, path.centroid, p.first, p.last, path.first, path.last);
        EXPECT_NEAR(p.total, path.total, tolerance) << integrator;
        EXPECT_NEAR(p.centroid, path.centroid, 0.5) << integrator;
        EXPECT_NEAR(p.first, path.first, 1) << integrator;
        EXPECT_NEAR(p.last, path.last, 1) << integrator;
    }
}

// A moving shape inside an object definition stays animated in each instance, as pbrt-v4 keeps it (the
// definition's animated shapes): the instance's transform times the shape's moving one, at each time.
TEST(MotionBlur, AMovingShapeInAnInstanceIsAMovingShape) {
    const int spp = 1024;
    Image shape = render(moving_sphere_scene(), spp);
    // The definition's motion, placed by a still use, or by a moving one that adds to it: each puts the
    // sphere where the moving shape has it at every time.
    auto instance = [&](double from, double to, const std::string& use) {
        return options(kStillCamera) + fmt::format(R"(
ObjectBegin "ball"
  {}
ObjectEnd
AttributeBegin
  {}
  ObjectInstance "ball"
AttributeEnd
)",
                                                   moving_sphere(from, to), use);
    };
    std::string cases[] = {
        instance(kFrom, kTo, ""),
        instance(kFrom + 1, kTo + 1, "Translate -1 0 3"), // depth is invisible to the orthographic camera
        instance(kFrom / 2, kTo / 2, translation_motion(kFrom / 2, kTo / 2)),
    };
    for (const std::string& text : cases) {
        auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
        EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
        EXPECT_TRUE(scene->has_motion);
        Image img = render(text, spp);
        for (int i = 0; i < kPixels; ++i)
            EXPECT_NEAR(img.at(i, 0).g, shape.at(i, 0).g, 2.0 / spp) << "pixel " << i << "\n" << text;
    }
}

TEST(MotionBlur, AMovingShapeInATurnedInstanceCoversTheFractionOfTheShutter) {
    // The definition moves the sphere along its y; the use turns it by -90° about z, so the sphere sweeps
    // the world's x from kFrom to kTo: the coverage is the closed form of the moving shape.
    const int spp = 4096;
    std::string text = options(kStillCamera) + fmt::format(R"(
ObjectBegin "ball"
  ActiveTransform StartTime
  Translate 0 {0} 0
  ActiveTransform EndTime
  Translate 0 {1} 0
  ActiveTransform All
  Scale 1 1 2
  Shape "sphere" "float radius" [{2}]
ObjectEnd
Rotate -90 0 0 1
ObjectInstance "ball"
)",
                                                           kFrom, kTo, kRadius);
    Image img = render(text, spp);
    for (int i = 0; i < kPixels; ++i) {
        double f = covered_fraction(pixel_x(i)), sigma = std::sqrt(f * (1 - f) / spp);
        EXPECT_NEAR(img.at(i, 0).g, 1 - f, 4 * sigma + 1e-5) << "pixel " << i;
    }
}

TEST(MotionBlur, UnsupportedCasesWarnAtTheirPosition) {
    // pbrt-v4 rejects moving area lights; illum moves them, and warns when "power" sets the radiance of one
    // whose size changes (from its start pose's area: tests/scenes/moving_area_light_test.cpp).
    std::string text = options(kStillCamera) + R"(AttributeBegin
ActiveTransform EndTime
Scale 2 1 1
AreaLightSource "diffuse" "float power" [2]
Shape "sphere"
AttributeEnd
)";
    auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
    ASSERT_EQ(scene->warnings.size(), 1u);
    EXPECT_NE(scene->warnings[0].find("<test>:14:1: a moving area light whose motion changes its size"),
              std::string::npos)
        << scene->warnings[0];
}

} // namespace
} // namespace illum
