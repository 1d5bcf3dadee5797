// Cameras follow pbrt's conventions (fov of the shorter axis, +x right and +y up in the image); the thin
// lens focuses at its focal distance; pixel filters are sampled in proportion to their value.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "illum/camera/camera.h"
#include "illum/camera/film.h"
#include "illum/camera/filter.h"
#include "illum/math/rng.h"

namespace illum {
namespace {

// The ray of a projective camera, which never fails and weighs 1.
Ray ray_of(const Camera& cam, Point2f p, Point2f u) {
    std::optional<CameraRay> r = cam.generate_ray(p, u, kDLineNm);
    EXPECT_TRUE(r && r->weight == 1);
    return r ? r->ray : Ray{};
}

TEST(PerspectiveCamera, FieldOfViewIsTheShorterAxis) {
    // Wide image: the vertical edges are at ±fov/2; the horizontal ones at ±atan(aspect tan(fov/2)).
    PerspectiveCamera cam(Transform(), 200, 100, 60.0f);
    Ray top = ray_of(cam, {100, 0}, {0.5f, 0.5f});
    EXPECT_NEAR(std::atan2(top.d.y, top.d.z), 30 * kPi / 180, 1e-5);
    Ray left = ray_of(cam, {0, 50}, {0.5f, 0.5f});
    EXPECT_NEAR(std::atan2(-left.d.x, left.d.z), std::atan(2 * std::tan(30 * kPi / 180)), 1e-5);
    Ray center = ray_of(cam, {100, 50}, {0.5f, 0.5f});
    EXPECT_NEAR(center.d.z, 1, 1e-6);
    // Raster +x is camera +x (right), raster +y is camera -y (down).
    EXPECT_GT(ray_of(cam, {150, 50}, {}).d.x, 0);
    EXPECT_LT(ray_of(cam, {100, 80}, {}).d.y, 0);
    // Tall image: the horizontal edges are at ±fov/2.
    PerspectiveCamera tall(Transform(), 100, 200, 60.0f);
    Ray l2 = ray_of(tall, {0, 100}, {0.5f, 0.5f});
    EXPECT_NEAR(std::atan2(-l2.d.x, l2.d.z), 30 * kPi / 180, 1e-5);
}

TEST(PerspectiveCamera, WorldFromCameraPlacesTheEye) {
    Transform camera_from_world = Transform::look_at({1, 2, 3}, {1, 2, 10}, {0, 1, 0});
    PerspectiveCamera cam(camera_from_world.inverse(), 64, 64, 45.0f);
    Ray r = ray_of(cam, {32, 32}, {0.5f, 0.5f});
    EXPECT_NEAR(r.o.x, 1, 1e-5);
    EXPECT_NEAR(r.o.y, 2, 1e-5);
    EXPECT_NEAR(r.o.z, 3, 1e-5);
    EXPECT_NEAR(r.d.z, 1, 1e-5);
}

TEST(PerspectiveCamera, ThinLensRaysMeetAtTheFocalDistance) {
    const float focal = 4.0f;
    PerspectiveCamera cam(Transform(), 64, 64, 40.0f, 0.2f, focal);
    PerspectiveCamera pinhole(Transform(), 64, 64, 40.0f);
    PCG32 rng(3);
    for (int i = 0; i < 200; ++i) {
        Point2f p{rng.uniform_float() * 64, rng.uniform_float() * 64};
        Point2f u{rng.uniform_float(), rng.uniform_float()};
        Ray r = ray_of(cam, p, u), c = ray_of(pinhole, p, u);
        // The pinhole ray through the same film point meets the plane z = focal where the lens ray does.
        Point3f a = r((focal - r.o.z) / r.d.z), b = c((focal - c.o.z) / c.d.z);
        EXPECT_NEAR(a.x, b.x, 1e-4);
        EXPECT_NEAR(a.y, b.y, 1e-4);
        EXPECT_LE(std::hypot(r.o.x, r.o.y), 0.2f + 1e-6f);
    }
}

TEST(OrthographicCamera, ParallelRaysOverTheScreenWindow) {
    Screen s{-2, 2, -1, 1};
    OrthographicCamera cam(Transform(), 80, 40, 0, 1e6f, &s);
    Ray a = ray_of(cam, {0, 0}, {}), b = ray_of(cam, {80, 40}, {});
    EXPECT_NEAR(a.o.x, -2, 1e-5);
    EXPECT_NEAR(a.o.y, 1, 1e-5);
    EXPECT_NEAR(b.o.x, 2, 1e-5);
    EXPECT_NEAR(b.o.y, -1, 1e-5);
    EXPECT_EQ(a.d, (Vector3f{0, 0, 1}));
}

// Chi-square test of a filter's samples against its evaluate(): 1D marginals over 40 bins (the filters
// are separable products), 200k samples, 1% significance.
void expect_samples_follow(const Filter& f, int axis) {
    const int bins = 40, n = 200000;
    const float r = f.radius()[axis];
    std::vector<double> observed(bins, 0), expected(bins, 0);
    PCG32 rng(11);
    for (int i = 0; i < n; ++i) {
        FilterSample s = f.sample({rng.uniform_float(), rng.uniform_float()});
        EXPECT_FLOAT_EQ(s.weight, 1.0f);
        float x = s.offset[axis];
        ASSERT_LE(std::abs(x), r * (1 + 1e-5f));
        int b = std::min(bins - 1, int((x + r) / (2 * r) * bins));
        observed[b] += 1;
    }
    // Expected counts from the filter's marginal, integrated by the midpoint rule on a fine grid.
    double total = 0;
    for (int b = 0; b < bins; ++b) {
        for (int k = 0; k < 64; ++k) {
            float x = -r + 2 * r * (b + (k + 0.5f) / 64) / bins;
            Vector2f p = axis == 0 ? Vector2f{x, 0} : Vector2f{0, x};
            expected[b] += f.evaluate(p);
        }
        total += expected[b];
    }
    double chi2 = 0;
    int dof = -1;
    for (int b = 0; b < bins; ++b) {
        double e = expected[b] / total * n;
        if (e < 5) continue;
        chi2 += (observed[b] - e) * (observed[b] - e) / e;
        ++dof;
    }
    // 99th percentile of chi-square with dof degrees of freedom (Wilson-Hilferty approximation).
    double z = 2.3263, k = dof;
    double crit = k * std::pow(1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k)), 3);
    EXPECT_LT(chi2, crit) << "dof " << dof;
}

TEST(Filter, SamplesFollowTheFilter) {
    for (int axis = 0; axis < 2; ++axis) {
        expect_samples_follow(BoxFilter({0.5f, 1.5f}), axis);
        expect_samples_follow(TriangleFilter({1.0f, 2.0f}), axis);
        expect_samples_follow(GaussianFilter({1.5f, 2.0f}, 0.5f), axis);
        expect_samples_follow(GaussianFilter({2.0f, 1.0f}, 0.8f), axis);
    }
}

// The filters with negative lobes (mitchell, sinc): their samples weighted by f/pdf estimate f's integral over
// every bin of each axis (the sample mean of w·[x in bin] against the midpoint rule, within 4.5 standard errors
// plus the table's resolution: pbrt-v4 tabulates f at 32 cells per unit radius).
void expect_weights_follow(const Filter& f, int axis) {
    const int bins = 16, n = 400000;
    const float r = f.radius()[axis], ro = f.radius()[1 - axis];
    std::vector<double> sum(bins, 0), sum2(bins, 0);
    PCG32 rng(5);
    double abs_integral = 0;
    for (int i = 0; i < n; ++i) {
        FilterSample s = f.sample({rng.uniform_float(), rng.uniform_float()});
        ASSERT_LE(std::abs(s.offset[axis]), r * (1 + 1e-5f));
        int b = std::min(bins - 1, int((s.offset[axis] + r) / (2 * r) * bins));
        sum[b] += s.weight;
        sum2[b] += double(s.weight) * s.weight;
        abs_integral += std::abs(s.weight) / n;
    }
    for (int b = 0; b < bins; ++b) {
        double expected = 0;
        const int k = 64;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < 4 * k; ++j) {
                float x = -r + 2 * r * (b + (i + 0.5f) / k) / bins, y = -ro + 2 * ro * (j + 0.5f) / (4 * k);
                expected += f.evaluate(axis == 0 ? Vector2f{x, y} : Vector2f{y, x});
            }
        expected *= (2 * r / bins / k) * (2 * ro / (4 * k));
        double mean = sum[b] / n, se = std::sqrt((sum2[b] / n - mean * mean) / n);
        EXPECT_NEAR(mean, expected, 4.5 * se + 2e-3 * abs_integral) << "bin " << b << " axis " << axis;
    }
}

TEST(Filter, NegativeLobedFiltersWeighTheirSamples) {
    for (int axis = 0; axis < 2; ++axis) {
        expect_weights_follow(MitchellFilter({2, 2}), axis);
        expect_weights_follow(MitchellFilter({1.5f, 2.5f}, 0.0f, 0.5f), axis); // Catmull-Rom
        expect_weights_follow(LanczosSincFilter({4, 4}, 3), axis);
    }
    // Mitchell-Netravali filters integrate to 1 over |x| < 2 per axis: ∫f = (r/2)² for radius r.
    EXPECT_NEAR(MitchellFilter::mitchell_1d(0, 1.0f / 3, 1.0f / 3), 16.0f / 18, 1e-6f);
    double integral = 0;
    for (int i = 0; i < 4000; ++i) integral += MitchellFilter::mitchell_1d(-2 + 4 * (i + 0.5) / 4000, 0.3f, 0.35f) * 4 / 4000;
    EXPECT_NEAR(integral, 1, 1e-5);
}

// A tent sampled as if it were a box.
struct BoxSampledTent final : Filter {
    BoxSampledTent() : Filter({1, 1}) {}
    float evaluate(Vector2f p) const override {
        return std::max(0.0f, 1 - std::abs(p.x)) * std::max(0.0f, 1 - std::abs(p.y));
    }
    FilterSample sample(Point2f u) const override { return {{2 * u.x - 1, 2 * u.y - 1}, 1}; }
};

TEST(Filter, WrongSamplingIsRejected) {
    // The same test fails for a wrongly sampled filter: the machinery can reject.
    EXPECT_NONFATAL_FAILURE(expect_samples_follow(BoxSampledTent(), 0), "dof");
}

TEST(Film, ResolvesTheWeightedMean) {
    Film film(2, 1);
    film.add_sample(0, 0, Color3(1, 2, 3), 1);
    film.add_sample(0, 0, Color3(3, 2, 1), 1);
    film.add_sample(1, 0, Color3(4, 4, 4), 0.5f);
    Image img = film.resolve();
    EXPECT_EQ(img(0, 0), Color3(2, 2, 2));
    EXPECT_EQ(img(1, 0), Color3(4, 4, 4));
}

} // namespace
} // namespace illum
