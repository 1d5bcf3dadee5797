// Every warp's pdf is checked three ways (DESIGN.md §4.1):
//  1. Monte Carlo: the mean of g(x)/pdf(x) over samples estimates ∫ g over the domain. With g = 1 this is
//     the domain's measure; with a non-constant g of known integral it also tests where samples go. The
//     tolerance is kSigmas standard errors of the estimate (from the sample variance), plus a float
//     rounding floor for estimators whose variance is zero.
//  2. Chi-square: a histogram of samples against the pdf integrated over each bin (fixed seed,
//     significance 1%).
//  3. Jacobian: pdf(warp(u)) = 1 / |det ∂warp/∂u|, the determinant by central differences.
// Negative controls at the end show each check rejects a wrong pdf.
#include "illum/math/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "illum/math/rng.h"
#include "math/stat_util.h"

namespace illum {
namespace {

using test::chi2_test;
using test::Chi2Result;
using test::MeanAccumulator;

constexpr double kSigmas = 5;          // two-sided false alarm 5.7e-7 per check under the normal approx.
constexpr double kSignificance = 0.01; // chi-square tests
constexpr int kMcSamples = 400000;
constexpr int kChi2Samples = 400000;

struct McResult {
    double estimate, std_error, expected;
    bool ok() const {
        // Floor: float warps and pdfs carry ~1e-6 relative rounding even when the variance is zero.
        double tol = kSigmas * std_error + 1e-5 * std::abs(expected);
        return std::abs(estimate - expected) <= tol;
    }
};

::testing::AssertionResult mc_ok(const McResult& r) {
    std::printf("  mc %.6g expected %.6g (%.2f standard errors)\n", r.estimate, r.expected,
                r.std_error > 0 ? (r.estimate - r.expected) / r.std_error : 0.0);
    if (r.ok()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "estimate " << r.estimate << " expected " << r.expected
                                         << " (standard error " << r.std_error << ")";
}

::testing::AssertionResult chi2_ok(const Chi2Result& r) {
    std::printf("  chi2 %.1f dof %d p %.3f\n", r.statistic, r.dof, r.p_value);
    if (r.p_value >= kSignificance) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value;
}

// ---------------------------------------------------------------------------------------------------------
// Direction warps. The histogram is over (z, φ) in [zmin, zmax] x [0, 2π): dω = dz dφ, so a bin's
// probability is ∫∫ pdf dz dφ, integrated by a midpoint rule on a sub-grid (exact for pdfs linear in z).

using DirWarp = std::function<Vector3f(Point2f)>;
using DirPdf = std::function<float(Vector3f)>;

McResult mc_directions(const DirWarp& warp, const DirPdf& pdf, const std::function<double(Vector3f)>& g,
                       double expected, uint64_t seed) {
    PCG32 rng(seed);
    MeanAccumulator acc;
    for (int i = 0; i < kMcSamples; ++i) {
        Point2f u{rng.uniform_float(), rng.uniform_float()};
        Vector3f w = warp(u);
        acc.add(g(w) / pdf(w));
    }
    return {acc.mean, acc.std_error(), expected};
}

Chi2Result chi2_directions(const DirWarp& warp, const DirPdf& pdf, double zmin, double zmax, uint64_t seed,
                           int nz = 10, int nphi = 20) {
    std::vector<double> observed(static_cast<size_t>(nz * nphi)), expected(static_cast<size_t>(nz * nphi));
    PCG32 rng(seed);
    for (int i = 0; i < kChi2Samples; ++i) {
        Point2f u{rng.uniform_float(), rng.uniform_float()};
        Vector3f w = warp(u);
        int iz = std::clamp(int((w.z - zmin) / (zmax - zmin) * nz), 0, nz - 1);
        int ip = std::clamp(int(spherical_phi(w) / (2 * kPiD) * nphi), 0, nphi - 1);
        observed[size_t(iz * nphi + ip)] += 1;
    }
    const int sub = 8;
    const double dz = (zmax - zmin) / nz, dphi = 2 * kPiD / nphi;
    for (int iz = 0; iz < nz; ++iz)
        for (int ip = 0; ip < nphi; ++ip) {
            double mass = 0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double z = zmin + (iz + (a + 0.5) / sub) * dz;
                    double phi = (ip + (b + 0.5) / sub) * dphi;
                    double s = std::sqrt(std::max(0.0, 1 - z * z));
                    Vector3f w(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
                    mass += pdf(w) * (dz / sub) * (dphi / sub);
                }
            expected[size_t(iz * nphi + ip)] = mass * kChi2Samples;
        }
    return chi2_test(observed, expected);
}

// Largest relative deviation of pdf(warp(u)) from 1 / |∂w/∂u x ∂w/∂v| over random u with
// skip(u) false. Central differences with step h: truncation O(h^2) ~ 1e-6 and float rounding
// ~ eps / h ~ 1e-4 relative, so deviations above 2e-3 are real.
constexpr float kFdStep = 1e-3f;
constexpr double kFdTolerance = 2e-3;

template <typename Map, typename Measure, typename Pdf>
double max_jacobian_error(Map map, Measure jacobian, Pdf pdf, const std::function<bool(Point2f)>& skip,
                          uint64_t seed, int count = 2000) {
    PCG32 rng(seed);
    double worst = 0;
    int tested = 0;
    while (tested < count) {
        Point2f u{0.01f + 0.98f * rng.uniform_float(), 0.01f + 0.98f * rng.uniform_float()};
        if (skip && skip(u)) continue;
        ++tested;
        const float h = kFdStep;
        Point2f ux0{u.x - h, u.y}, ux1{u.x + h, u.y}, uy0{u.x, u.y - h}, uy1{u.x, u.y + h};
        double jac =
            jacobian(map(ux0), map(ux1), map(uy0), map(uy1), double(ux1.x - ux0.x), double(uy1.y - uy0.y));
        double p = pdf(map(u));
        worst = std::max(worst, std::abs(p * jac - 1));
    }
    return worst;
}

double direction_jacobian(Vector3f x0, Vector3f x1, Vector3f y0, Vector3f y1, double dx, double dy) {
    double ax = (double(x1.x) - x0.x) / dx, ay = (double(x1.y) - x0.y) / dx, az = (double(x1.z) - x0.z) / dx;
    double bx = (double(y1.x) - y0.x) / dy, by = (double(y1.y) - y0.y) / dy, bz = (double(y1.z) - y0.z) / dy;
    double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    return std::sqrt(cx * cx + cy * cy + cz * cz);
}

double plane_jacobian(Point2f x0, Point2f x1, Point2f y0, Point2f y1, double dx, double dy) {
    double ax = (double(x1.x) - x0.x) / dx, ay = (double(x1.y) - x0.y) / dx;
    double bx = (double(y1.x) - y0.x) / dy, by = (double(y1.y) - y0.y) / dy;
    return std::abs(ax * by - ay * bx);
}

// The concentric map's derivative jumps on the square's diagonals: keep the stencil off them.
bool near_concentric_seam(Point2f u) {
    double ox = 2 * double(u.x) - 1, oy = 2 * double(u.y) - 1;
    return std::abs(std::abs(ox) - std::abs(oy)) < 8 * kFdStep ||
           (std::abs(ox) < 8 * kFdStep && std::abs(oy) < 8 * kFdStep);
}

// ---------------------------------------------------------------------------------------------------------
// Disk

void check_disk_warp(Point2f (*warp)(Point2f), bool concentric) {
    auto pdf = [](Point2f) { return double(uniform_disk_pdf()); };
    // MC: area π, and ∫ x² dA = π/4.
    for (int which = 0; which < 2; ++which) {
        PCG32 rng(7 + which);
        MeanAccumulator acc;
        for (int i = 0; i < kMcSamples; ++i) {
            Point2f p = warp({rng.uniform_float(), rng.uniform_float()});
            double g = which == 0 ? 1.0 : double(p.x) * p.x;
            acc.add(g / pdf(p));
        }
        EXPECT_TRUE(mc_ok({acc.mean, acc.std_error(), which == 0 ? kPiD : kPiD / 4}));
    }
    // Chi-square over (r², φ) bins, equal area each; also every sample inside the disk.
    const int nr = 10, nphi = 20;
    std::vector<double> observed(nr * nphi), expected(nr * nphi);
    PCG32 rng(11);
    int outside = 0;
    for (int i = 0; i < kChi2Samples; ++i) {
        Point2f p = warp({rng.uniform_float(), rng.uniform_float()});
        double r2 = double(p.x) * p.x + double(p.y) * p.y;
        outside += r2 > 1 + 1e-6;
        double phi = std::atan2(double(p.y), double(p.x));
        if (phi < 0) phi += 2 * kPiD;
        int ir = std::clamp(int(r2 * nr), 0, nr - 1),
            ip = std::clamp(int(phi / (2 * kPiD) * nphi), 0, nphi - 1);
        observed[size_t(ir * nphi + ip)] += 1;
    }
    for (int b = 0; b < nr * nphi; ++b) expected[size_t(b)] = pdf({}) * (kPiD / (nr * nphi)) * kChi2Samples;
    EXPECT_EQ(outside, 0);
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
    // Jacobian.
    double err = max_jacobian_error(
        warp, plane_jacobian, pdf, [&](Point2f u) { return concentric && near_concentric_seam(u); }, 13);
    EXPECT_LT(err, kFdTolerance);
}

TEST(Warp, DiskConcentric) { check_disk_warp(sample_uniform_disk_concentric, true); }
TEST(Warp, DiskPolar) { check_disk_warp(sample_uniform_disk_polar, false); }

TEST(Warp, DiskConcentricCornersAndCentre) {
    EXPECT_EQ(sample_uniform_disk_concentric({0.5f, 0.5f}), Point2f(0, 0));
    for (Point2f u : {Point2f(0, 0), Point2f(1, 0), Point2f(0, 1), Point2f(1, 1)}) {
        Point2f p = sample_uniform_disk_concentric(u);
        EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 1e-6);
    }
}

// ---------------------------------------------------------------------------------------------------------
// Hemisphere, cosine hemisphere, sphere, cone

TEST(Warp, UniformHemisphere) {
    auto warp = [](Point2f u) { return sample_uniform_hemisphere(u); };
    auto pdf = [](Vector3f w) { return w.z >= 0 ? uniform_hemisphere_pdf() : 0.0f; };
    EXPECT_TRUE(mc_ok(mc_directions(
        warp, pdf, [](Vector3f) { return 1.0; }, 2 * kPiD, 1)));
    // ∫ cos θ dω over the hemisphere = π.
    EXPECT_TRUE(mc_ok(mc_directions(
        warp, pdf, [](Vector3f w) { return double(w.z); }, kPiD, 2)));
    EXPECT_TRUE(chi2_ok(chi2_directions(warp, pdf, 0, 1, 3)));
    EXPECT_LT(max_jacobian_error(warp, direction_jacobian, pdf, nullptr, 4), kFdTolerance);
}

TEST(Warp, CosineHemisphere) {
    auto warp = [](Point2f u) { return sample_cosine_hemisphere(u); };
    auto pdf = [](Vector3f w) { return cosine_hemisphere_pdf(w.z); };
    // ∫ 1/pdf diverges in variance (1/cos θ at the horizon), so the measure check uses g = cos θ, whose
    // estimator is π exactly per sample, and the mean of cos θ under the pdf is 2/3 (= ∫ cos² θ dω / π).
    EXPECT_TRUE(mc_ok(mc_directions(
        warp, pdf, [](Vector3f w) { return double(w.z); }, kPiD, 1)));
    {
        PCG32 rng(2);
        MeanAccumulator cos_theta;
        for (int i = 0; i < kMcSamples; ++i)
            cos_theta.add(warp({rng.uniform_float(), rng.uniform_float()}).z);
        EXPECT_TRUE(mc_ok({cos_theta.mean, cos_theta.std_error(), 2.0 / 3.0}));
    }
    EXPECT_TRUE(chi2_ok(chi2_directions(warp, pdf, 0, 1, 3)));
    // Near the rim z -> 0 the map's derivative blows up; keep the stencil inside r < 0.9.
    auto skip = [](Point2f u) {
        return near_concentric_seam(u) || std::max(std::abs(2 * u.x - 1), std::abs(2 * u.y - 1)) > 0.9f;
    };
    EXPECT_LT(max_jacobian_error(warp, direction_jacobian, pdf, skip, 4), kFdTolerance);
}

TEST(Warp, UniformSphere) {
    auto warp = [](Point2f u) { return sample_uniform_sphere(u); };
    auto pdf = [](Vector3f) { return uniform_sphere_pdf(); };
    EXPECT_TRUE(mc_ok(mc_directions(
        warp, pdf, [](Vector3f) { return 1.0; }, 4 * kPiD, 1)));
    // ∫ z² dω = 4π/3.
    EXPECT_TRUE(mc_ok(mc_directions(
        warp, pdf, [](Vector3f w) { return double(w.z) * w.z; }, 4 * kPiD / 3, 2)));
    EXPECT_TRUE(chi2_ok(chi2_directions(warp, pdf, -1, 1, 3)));
    EXPECT_LT(max_jacobian_error(warp, direction_jacobian, pdf, nullptr, 4), kFdTolerance);
}

TEST(Warp, UniformCone) {
    for (float cos_max : {0.95f, 0.5f, 0.0f, -0.6f}) {
        SCOPED_TRACE(cos_max);
        auto warp = [=](Point2f u) { return sample_uniform_cone(u, cos_max); };
        auto pdf = [=](Vector3f w) { return w.z >= cos_max ? uniform_cone_pdf(cos_max) : 0.0f; };
        double c = cos_max;
        EXPECT_TRUE(mc_ok(mc_directions(
            warp, pdf, [](Vector3f) { return 1.0; }, 2 * kPiD * (1 - c), 1)));
        // ∫ cos θ dω over the cap = π (1 - cos² θmax).
        EXPECT_TRUE(mc_ok(mc_directions(
            warp, pdf, [](Vector3f w) { return double(w.z); }, kPiD * (1 - c * c), 2)));
        EXPECT_TRUE(chi2_ok(chi2_directions(warp, pdf, c, 1, 3)));
        EXPECT_LT(max_jacobian_error(warp, direction_jacobian, pdf, nullptr, 4), kFdTolerance);
    }
}

// ---------------------------------------------------------------------------------------------------------
// Triangle (area)

// Sub-triangles of the barycentric triangle at subdivision n: cells (i, j) with i + j < n, "up" triangles
// (i + j <= n - 1) and "down" ones (i + j <= n - 2). Returns the index of the sub-triangle holding (b1, b2).
int subtriangle_index(double b1, double b2, int n) {
    double x = std::clamp(b1 * n, 0.0, n - 1e-9), y = std::clamp(b2 * n, 0.0, n - 1e-9);
    int i = int(x), j = int(y);
    bool down = (x - i) + (y - j) >= 1;
    if (i + j > n - 1) { // numerically outside: fold back into the last up triangle of that row
        j = n - 1 - i;
        down = false;
    }
    if (down && i + j > n - 2) down = false;
    return (i * n + j) * 2 + (down ? 1 : 0);
}

// The three barycentric (b1, b2) corners of sub-triangle (i, j, down).
std::array<std::array<double, 2>, 3> subtriangle_corners(int i, int j, bool down, int n) {
    double s = 1.0 / n;
    if (!down) return {{{i * s, j * s}, {(i + 1) * s, j * s}, {i * s, (j + 1) * s}}};
    return {{{(i + 1) * s, j * s}, {i * s, (j + 1) * s}, {(i + 1) * s, (j + 1) * s}}};
}

TEST(Warp, UniformTriangle) {
    const Point3f v0(0, 0, 0), v1(3, 0.5f, 0), v2(1, 2, 1);
    const double area = 0.5 * double(length(cross(v1 - v0, v2 - v0)));
    auto point = [&](Point2f u) {
        auto b = sample_uniform_triangle(u);
        return barycentric(v0, v1, v2, b[0], b[1], b[2]);
    };
    auto pdf = [&](Point3f) { return 1.0 / area; };
    PCG32 rng(1);
    MeanAccumulator measure, mean_x;
    for (int i = 0; i < kMcSamples; ++i) {
        Point3f p = point({rng.uniform_float(), rng.uniform_float()});
        measure.add(1 / pdf(p));
        mean_x.add(p.x / pdf(p));
    }
    EXPECT_TRUE(mc_ok({measure.mean, measure.std_error(), area}));
    // ∫ x dA = area * centroid.x.
    EXPECT_TRUE(mc_ok({mean_x.mean, mean_x.std_error(), area * (v0.x + v1.x + v2.x) / 3.0}));

    // Histogram over the n² sub-triangles of equal area; barycentrics valid and summing to 1.
    const int n = 8;
    std::vector<double> observed(static_cast<size_t>(2 * n * n)), expected(static_cast<size_t>(2 * n * n));
    int invalid = 0;
    for (int i = 0; i < kChi2Samples; ++i) {
        auto b = sample_uniform_triangle({rng.uniform_float(), rng.uniform_float()});
        invalid += b[0] < 0 || b[1] < 0 || b[2] < 0 || std::abs(b[0] + b[1] + b[2] - 1) > 1e-6f;
        observed[size_t(subtriangle_index(b[1], b[2], n))] += 1;
    }
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            expected[size_t((i * n + j) * 2)] = kChi2Samples / double(n * n);
            if (i + j <= n - 2) expected[size_t((i * n + j) * 2 + 1)] = kChi2Samples / double(n * n);
        }
    EXPECT_EQ(invalid, 0);
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));

    // Jacobian of u -> point on the triangle (area measure); the map's derivative jumps on u.x = u.y.
    auto jac = [](Point3f x0, Point3f x1, Point3f y0, Point3f y1, double dx, double dy) {
        Vector3f a = (x1 - x0) / float(dx), b = (y1 - y0) / float(dy);
        return double(length(cross(a, b)));
    };
    auto skip = [](Point2f u) { return std::abs(u.x - u.y) < 4 * kFdStep; };
    EXPECT_LT(max_jacobian_error(point, jac, pdf, skip, 5), kFdTolerance);
}

// ---------------------------------------------------------------------------------------------------------
// Spherical triangle (solid angle)

Vector3f normalized(Point3f q, Point3f p) { return normalize(q - p); }

using Vec3d = std::array<double, 3>;
double dot_d(const Vec3d& x, const Vec3d& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
Vec3d cross_d(const Vec3d& a, const Vec3d& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d unit_d(const Vec3d& v) {
    double l = std::sqrt(dot_d(v, v));
    return {v[0] / l, v[1] / l, v[2] / l};
}

// Solid angle in double (Van Oosterom & Strackee), independent of the float implementation.
double solid_angle_d(const Vec3d& a0, const Vec3d& b0, const Vec3d& c0) {
    auto a = unit_d(a0), b = unit_d(b0), c = unit_d(c0);
    double num = std::abs(dot_d(a, cross_d(b, c))), den = 1 + dot_d(a, b) + dot_d(b, c) + dot_d(c, a);
    return 2 * std::atan2(num, den);
}

std::array<double, 3> rel(Point3f q, Point3f p) {
    return {double(q.x) - p.x, double(q.y) - p.y, double(q.z) - p.z};
}

struct SphTriCase {
    std::array<Point3f, 3> v;
    Point3f p;
};

const SphTriCase kSphTriCases[] = {
    {{Point3f(-1, -1, 1), Point3f(1, -1, 1), Point3f(0, 1, 1)}, Point3f(0, 0, 0)},          // ~1.3 sr
    {{Point3f(0, 0, 1), Point3f(4, 0, 0.2f), Point3f(0, 5, 0.3f)}, Point3f(0.1f, 0.1f, 0)}, // large, obtuse
    {{Point3f(0.2f, 0.1f, 5), Point3f(0.5f, 0.1f, 5), Point3f(0.3f, 0.4f, 5.5f)}, Point3f(0, 0, 0)}, // small
    {{Point3f(1, 0, 0.05f), Point3f(0, 1, 0.05f), Point3f(-1, -1, 0.3f)}, Point3f(0, 0, 0)}, // grazing
};

TEST(Warp, SphericalTriangleAreaMatchesDouble) {
    for (const auto& c : kSphTriCases) {
        double ref = solid_angle_d(rel(c.v[0], c.p), rel(c.v[1], c.p), rel(c.v[2], c.p));
        float got = spherical_triangle_area(normalized(c.v[0], c.p), normalized(c.v[1], c.p),
                                            normalized(c.v[2], c.p));
        EXPECT_NEAR(got, ref, 1e-5 * ref);
    }
    // The hemisphere-sized case: three orthogonal axes bound one octant, π/2 sr.
    EXPECT_NEAR(spherical_triangle_area({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), kPiD / 2, 1e-6);
}

TEST(Warp, SphericalTriangle) {
    int case_index = 0;
    for (const auto& c : kSphTriCases) {
        SCOPED_TRACE(case_index++);
        const double omega = solid_angle_d(rel(c.v[0], c.p), rel(c.v[1], c.p), rel(c.v[2], c.p));
        PCG32 rng(100 + case_index);
        MeanAccumulator measure;
        MeanAccumulator dir[3];
        double worst_pdf = 0;
        int bad = 0;
        const int n = 6;
        std::vector<double> observed(static_cast<size_t>(2 * n * n)),
            expected(static_cast<size_t>(2 * n * n));
        for (int i = 0; i < kMcSamples; ++i) {
            float pdf;
            auto b = sample_spherical_triangle(c.v, c.p, {rng.uniform_float(), rng.uniform_float()}, &pdf);
            bad += !(pdf > 0) || !std::isfinite(b[0] + b[1] + b[2]) || b[0] < 0 || b[1] < 0 || b[2] < 0;
            worst_pdf = std::max(worst_pdf, std::abs(pdf * omega - 1));
            Vector3f w = normalized(barycentric(c.v[0], c.v[1], c.v[2], b[0], b[1], b[2]), c.p);
            measure.add(1 / pdf);
            for (int k = 0; k < 3; ++k) dir[k].add(w[k] / pdf);
            observed[size_t(subtriangle_index(b[1], b[2], n))] += 1;
        }
        EXPECT_EQ(bad, 0);
        // pdf = 1 / solid angle; the float angle sum loses ~1e-6 sr absolutely.
        EXPECT_LT(worst_pdf, 1e-4 + 4e-6 / omega);
        EXPECT_TRUE(mc_ok({measure.mean, measure.std_error(), omega}));

        // ∫ w dω over a spherical polygon = ½ Σ_edges θ_e n_e (Arvo 1995, the vector irradiance), n_e the
        // unit normal of the edge's great circle and θ_e the edge's arc length; oriented towards the
        // triangle's interior.
        // Computed in double: the terms cancel to ~Ω, so float directions are not accurate enough.
        std::array<double, 3> expect{0, 0, 0};
        for (int e = 0; e < 3; ++e) {
            auto a = unit_d(rel(c.v[size_t(e)], c.p)), bb = unit_d(rel(c.v[size_t((e + 1) % 3)], c.p));
            auto nrm = unit_d(cross_d(a, bb));
            double theta = std::acos(std::clamp(dot_d(a, bb), -1.0, 1.0));
            for (int k = 0; k < 3; ++k) expect[size_t(k)] += 0.5 * theta * nrm[size_t(k)];
        }
        auto centroid = rel(barycentric(c.v[0], c.v[1], c.v[2], 1 / 3.f, 1 / 3.f, 1 / 3.f), c.p);
        double sgn = dot_d(expect, centroid) < 0 ? -1 : 1;
        for (int k = 0; k < 3; ++k) {
            SCOPED_TRACE(k);
            EXPECT_TRUE(mc_ok({dir[k].mean, dir[k].std_error(), sgn * expect[size_t(k)]}));
        }

        // Histogram over sub-triangles against their solid angles.
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j)
                for (int down = 0; down < 2; ++down) {
                    if (down && i + j > n - 2) continue;
                    auto corners = subtriangle_corners(i, j, down, n);
                    std::array<std::array<double, 3>, 3> d;
                    for (int k = 0; k < 3; ++k) {
                        double b1 = corners[size_t(k)][0], b2 = corners[size_t(k)][1], b0 = 1 - b1 - b2;
                        for (int a = 0; a < 3; ++a)
                            d[size_t(k)][size_t(a)] =
                                b0 * c.v[0][a] + b1 * c.v[1][a] + b2 * c.v[2][a] - c.p[a];
                    }
                    expected[size_t((i * n + j) * 2 + down)] =
                        solid_angle_d(d[0], d[1], d[2]) / omega * kMcSamples;
                }
        EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
    }
}

TEST(Warp, SphericalTriangleJacobian) {
    for (const auto& c : kSphTriCases) {
        const double omega = solid_angle_d(rel(c.v[0], c.p), rel(c.v[1], c.p), rel(c.v[2], c.p));
        auto dirf = [&](Point2f u) {
            float pdf;
            auto b = sample_spherical_triangle(c.v, c.p, u, &pdf);
            return normalized(barycentric(c.v[0], c.v[1], c.v[2], b[0], b[1], b[2]), c.p);
        };
        auto pdf = [&](Vector3f) { return 1 / omega; };
        // Float rounding in the directions is relative to 1 while the Jacobian scales like the solid angle:
        // for the small case allow eps / (h · sqrt(Ω)).
        double tol = kFdTolerance + 6e-8 / (kFdStep * std::sqrt(omega));
        EXPECT_LT(max_jacobian_error(dirf, direction_jacobian, pdf, nullptr, 9, 500), tol);
    }
}

TEST(Warp, SphericalTriangleDegenerate) {
    const std::array<Point3f, 3> tri{Point3f(0, 0, 0), Point3f(1, 0, 0), Point3f(0, 1, 0)};
    PCG32 rng(3);
    // Seen edge-on (p in the triangle's plane, inside or outside it), from a vertex, and a collapsed
    // triangle.
    const Point3f views[] = {Point3f(2, 2, 0), Point3f(0.2f, 0.2f, 0), Point3f(-1, 0, 0), Point3f(0, 0, 0)};
    for (Point3f p : views) {
        for (int i = 0; i < 100; ++i) {
            float pdf = -1;
            auto b = sample_spherical_triangle(tri, p, {rng.uniform_float(), rng.uniform_float()}, &pdf);
            EXPECT_EQ(pdf, 0.0f);
            for (float x : b) EXPECT_TRUE(std::isfinite(x));
        }
    }
    const std::array<Point3f, 3> line{Point3f(0, 0, 0), Point3f(1, 0, 0), Point3f(2, 0, 0)};
    float pdf = -1;
    auto b = sample_spherical_triangle(line, Point3f(0, 0, 1), {0.3f, 0.6f}, &pdf);
    EXPECT_EQ(pdf, 0.0f);
    for (float x : b) EXPECT_TRUE(std::isfinite(x));
    // Nearly edge-on: still finite and a positive pdf that is 1 / solid angle.
    Point3f p(0.3f, 0.3f, 1e-3f);
    auto b2 = sample_spherical_triangle(tri, p, {0.5f, 0.5f}, &pdf);
    for (float x : b2) EXPECT_TRUE(std::isfinite(x));
    double omega = solid_angle_d(rel(tri[0], p), rel(tri[1], p), rel(tri[2], p));
    EXPECT_NEAR(pdf * omega, 1.0, 1e-3);
}

// ---------------------------------------------------------------------------------------------------------
// Negative controls: the checks above reject wrong pdfs.

TEST(WarpChecks, RejectWrongPdf) {
    auto cosine = [](Point2f u) { return sample_cosine_hemisphere(u); };
    auto wrong = [](Vector3f) { return uniform_hemisphere_pdf(); };
    EXPECT_LT(chi2_directions(cosine, wrong, 0, 1, 3).p_value, 1e-9);
    EXPECT_FALSE(mc_directions(
                     cosine, wrong, [](Vector3f w) { return double(w.z); }, kPiD, 1)
                     .ok());
    // A pdf off by 1% fails the Jacobian check.
    auto sphere = [](Point2f u) { return sample_uniform_sphere(u); };
    auto off = [](Vector3f) { return 1.01f * uniform_sphere_pdf(); };
    EXPECT_GT(max_jacobian_error(sphere, direction_jacobian, off, nullptr, 4), kFdTolerance);
    // Uniform-in-z samples on the hemisphere are not cosine distributed.
    auto hemi = [](Point2f u) { return sample_uniform_hemisphere(u); };
    auto cos_pdf = [](Vector3f w) { return cosine_hemisphere_pdf(w.z); };
    EXPECT_LT(chi2_directions(hemi, cos_pdf, 0, 1, 3).p_value, 1e-9);
}

TEST(WarpChecks, GammaQ) {
    // Q(k/2, x/2) is the chi-square survival function: known values.
    EXPECT_NEAR(test::gamma_q(0.5, 3.841458820694124 / 2), 0.05, 1e-9); // dof 1
    EXPECT_NEAR(test::gamma_q(5, 23.209251158954356 / 2), 0.01, 1e-9);  // dof 10
    EXPECT_NEAR(test::gamma_q(50, 135.80672317102676 / 2), 0.01, 1e-9); // dof 100
    EXPECT_NEAR(test::gamma_q(1, 2), std::exp(-2.0), 1e-12);
}

} // namespace
} // namespace illum
