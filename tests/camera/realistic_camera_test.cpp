// RealisticCamera's sampling: the exit-pupil bounds hold every ray that passes the lens, so the camera's
// mean weight is the film irradiance factor E / L = (1 / z²) ∫ cos⁴θ dA over the passing rays, found here
// by brute force; the image is upright; the stop shapes keep the exposure of the circular stop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "illum/camera/aperture_shape.h"
#include "illum/math/rng.h"
#include "lens_support.h"

namespace illum {
namespace {

// Like pbrt-v4's TestExitPupilBounds: random film points and random targets in the rear element's disk;
// every ray that passes must aim inside its bin's (rotated) box.
TEST(RealisticCamera, ExitPupilBoundsHoldEveryPassingRay) {
    ILLUM_REQUIRE_DGAUSS();
    for (double stop : {17.1, 4.0}) {
        RealisticCamera cam = test::make_camera(test::dgauss(), stop, 3, 36, 24, 43.27, 1 << 14);
        const LensSystem& lens = cam.lens();
        const ExitPupil& pupil = cam.exit_pupil();
        const double film_r = 43.27e-3 / 2, rear = 1.5 * lens.rear_aperture_radius();
        PCG32 rng(5);
        int passed = 0, outside = 0;
        for (int i = 0; i < 200000; ++i) {
            double r = film_r * rng.uniform_float(), phi = 2 * M_PI * rng.uniform_float();
            double tx = rear * (2 * rng.uniform_float() - 1), ty = rear * (2 * rng.uniform_float() - 1);
            double lambda = 360 + 470 * rng.uniform_float();
            LensVec pf{r * std::cos(phi), r * std::sin(phi), 0};
            LensRay ray{pf, LensVec{tx, ty, lens.film_distance()} - pf};
            if (lens.trace_from_film(ray, lambda, nullptr) == 0) continue;
            ++passed;
            // Back to the bin's frame (film point on +x).
            double bx = std::cos(phi) * tx + std::sin(phi) * ty,
                   by = -std::sin(phi) * tx + std::cos(phi) * ty;
            if (!pupil.bounds(pupil.bin_of(r)).contains(bx, by)) ++outside;
        }
        std::printf("stop %.1f mm: %d of 200000 rays pass, %d outside the bounds\n", stop, passed, outside);
        EXPECT_GT(passed, 1000);
        EXPECT_EQ(outside, 0);
    }
}

// The mean of generate_ray's weight over the lens samples (misses count as 0) against a brute-force
// (1 / z²) ∫ cos⁴θ V dA over the whole ±1.5 rear radius square, at the centre and towards the corner
// (where vignetting cuts the pupil): equal within the quadrature error of the two 400² grids (~1%).
TEST(RealisticCamera, MeanWeightIsTheIrradianceFactor) {
    ILLUM_REQUIRE_DGAUSS();
    RealisticCamera cam = test::make_camera(test::dgauss(), 17.1, 10, 360, 240, 43.27, 1 << 15);
    const LensSystem& lens = cam.lens();
    const int n = 400;
    std::vector<double> means;
    for (Point2f raster : {Point2f{180, 120}, Point2f{300, 60}, Point2f{350, 20}}) {
        double mean = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if (auto r = cam.generate_ray(raster, {(i + 0.5f) / n, (j + 0.5f) / n}, kDLineNm))
                    mean += r->weight;
        mean /= double(n) * n;
        LensVec pf = cam.film_point(raster);
        const double half = 1.5 * lens.rear_aperture_radius(), z = lens.film_distance(),
                     da = sqr(2 * half / n);
        double brute = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                LensVec t{-half + 2 * half * (i + 0.5) / n, -half + 2 * half * (j + 0.5) / n, z};
                LensRay ray{pf, t - pf};
                if (lens.trace_from_film(ray, kLambdaD, nullptr) == 0) continue;
                double c = normalize(ray.d).z;
                brute += c * c * c * c * da / (z * z);
            }
        std::printf("raster (%g, %g): mean weight %.5f, brute force %.5f\n", raster.x, raster.y, mean, brute);
        EXPECT_NEAR(mean, brute, 0.01 * brute);
        means.push_back(mean);
    }
    // f/2: the centre's factor is near π / (4 N²) = 0.196 (not exactly: the rear plane is not the exit
    // pupil's), and it falls towards the corner (cos⁴θ and vignetting).
    EXPECT_NEAR(means[0], M_PI / 16, 0.03);
    EXPECT_LT(means[1], means[0]);
    EXPECT_LT(means[2], means[1]);
}

TEST(RealisticCamera, ImageIsUprightAndRaysLeaveTheFrontElement) {
    ILLUM_REQUIRE_DGAUSS();
    RealisticCamera cam = test::make_camera(test::dgauss(), 8, 10, 360, 240, 43.27, 1 << 12);
    auto dir = [&](Point2f p) {
        std::optional<CameraRay> r = cam.generate_ray(p, {0.5f, 0.5f}, kDLineNm);
        EXPECT_TRUE(r);
        EXPECT_NEAR(r->ray.o.z, cam.lens().front_z(), 3e-3); // on the front surface (sag < 3 mm)
        return r->ray.d;
    };
    // As the perspective camera: raster +x looks to camera +x, raster +y to camera -y.
    EXPECT_GT(dir({300, 120}).x, 0.05f);
    EXPECT_LT(dir({60, 120}).x, -0.05f);
    EXPECT_LT(dir({180, 200}).y, -0.05f);
    EXPECT_GT(dir({180, 20}).y, 0.05f);
    EXPECT_NEAR(dir({180, 120}).z, 1, 1e-4);
    // Far outside the lens's field nothing passes.
    RealisticCamera wide = test::make_camera(test::dgauss(), 8, 10, 360, 240, 200, 1 << 12);
    EXPECT_FALSE(wide.generate_ray({0, 0}, {0.5f, 0.5f}, kDLineNm));
}

// Each built-in stop shape integrates to π over [-1, 1]² (the unit disk's area), so it keeps the
// exposure; and each has its shape.
TEST(ApertureShape, BuiltInShapesKeepTheExposure) {
    for (const char* name : {"gaussian", "square", "pentagon", "star"}) {
        auto shape = builtin_aperture(name);
        ASSERT_TRUE(shape) << name;
        const int n = 1000;
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                sum += shape->transmission(-1 + (i + 0.5) * 2.0 / n, -1 + (j + 0.5) * 2.0 / n);
        EXPECT_NEAR(sum * 4.0 / (double(n) * n), M_PI, 0.005 * M_PI) << name;
    }
    EXPECT_FALSE(builtin_aperture("hexagon"));
    EXPECT_FALSE(builtin_aperture("circular"));
    auto square = builtin_aperture("square"), pentagon = builtin_aperture("pentagon"),
         star = builtin_aperture("star");
    EXPECT_GT(square->transmission(0.45, 0.45), 0);
    EXPECT_EQ(square->transmission(0.55, 0), 0);
    EXPECT_GT(pentagon->transmission(0, -0.75), 0); // apex at -v
    EXPECT_EQ(pentagon->transmission(0, 0.75), 0);
    EXPECT_GT(star->transmission(-0.9, 0), 0); // a tip at 180°
    EXPECT_EQ(star->transmission(0.9, 0), 0);  // an inner corner at 0°
    EXPECT_GT(builtin_aperture("gaussian")->transmission(0, 0),
              builtin_aperture("gaussian")->transmission(0.5, 0));
}

// An image stop: the file's top row at +v, black outside, scaled to the circular stop's integral.
TEST(ApertureShape, ImageStopIsScaledAndOriented) {
    Image im(4, 4, Color3(0.0f));
    im(1, 0) = Color3(1.0f); // top row
    auto shape = image_aperture(im);
    // Pixel (1, 0) has its centre at u = -0.25, v = +0.75; mean 1/16 -> scale (π/4) / (1/16) = 4π.
    EXPECT_NEAR(shape->transmission(-0.25, 0.75), 4 * M_PI, 1e-9);
    EXPECT_EQ(shape->transmission(-0.25, -0.75), 0);
    EXPECT_EQ(shape->transmission(-1.5, 0.75), 0);
    EXPECT_THROW(image_aperture(Image(2, 2, Color3(0.0f))), Error);
}

// A shaped stop changes which rays pass, not the centre's exposure (the shapes are normalised to the
// circle); here the square against the circle at the same stop diameter.
TEST(ApertureShape, CameraExposureIsKeptBySquareStop) {
    ILLUM_REQUIRE_DGAUSS();
    RealisticCamera::Settings s;
    s.focus_distance = 10;
    s.pupil_samples = 1 << 14;
    LensPrescription lens = test::dgauss();
    RealisticCamera round(Transform(), 360, 240, LensSystem::from_prescription(lens, 8), nullptr, s);
    RealisticCamera square(Transform(), 360, 240, LensSystem::from_prescription(lens, 8),
                           builtin_aperture("square"), s);
    auto mean_weight = [](const RealisticCamera& cam) {
        const int n = 300;
        double m = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if (auto r = cam.generate_ray({180, 120}, {(i + 0.5f) / n, (j + 0.5f) / n}, kDLineNm))
                    m += r->weight;
        return m / (double(n) * n);
    };
    double a = mean_weight(round), b = mean_weight(square);
    std::printf("mean centre weight: circular stop %.5f, square stop %.5f\n", a, b);
    EXPECT_NEAR(b, a, 0.02 * a);
}

} // namespace
} // namespace illum
