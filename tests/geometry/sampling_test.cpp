// Area and sampling of pbrt's analytic shapes: the exact area of partial and affinely transformed shapes
// against closed forms; sample_area() uniform over the partial surface (chi-square in the coordinates in
// which the area element is constant) and inside it; sample()'s pdf equal to pdf(), and pdf() integrating
// to 1 over the directions that reach the shape (Monte Carlo, within standard errors).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <memory>

#include "illum/geometry/cylinder.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/sphere.h"
#include "illum/math/frame.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "math/stat_util.h"

namespace illum {
namespace {

using test::MeanAccumulator;
constexpr double kDeg = kPiD / 180;

Transform similarity() {
    return Transform::translate({1, -2, 0.5f}) * Transform::rotate(70, {1, 1, 0}) * Transform::scale(2, 2, 2);
}
Transform non_uniform() {
    return Transform::translate({1, -2, 0.5f}) * Transform::rotate(70, {1, 1, 0}) *
           Transform::scale(1.5f, 0.6f, 1.1f);
}

TEST(AnalyticArea, PartialShapesUnderASimilarity) {
    // Sphere: φmax r (zmax - zmin), times s² = 4.
    SphereShape sphere(similarity(), 1.5f, -0.5f, 1.0f, float(200 * kDeg), false);
    EXPECT_NEAR(sphere.area(), 4 * 200 * kDeg * 1.5 * 1.5, 1e-5 * sphere.area());
    // zmin, zmax beyond the radius are clamped to it.
    SphereShape clamped(similarity(), 1.0f, -3.0f, 0.0f, float(2 * kPiD), false);
    EXPECT_NEAR(clamped.area(), 4 * 2 * kPiD, 1e-5 * clamped.area());
    DiskShape disk(similarity(), 0.3f, 2.0f, 0.5f, false, float(120 * kDeg));
    EXPECT_NEAR(disk.area(), 4 * 120 * kDeg / 2 * (4 - 0.25), 1e-5 * disk.area());
    CylinderShape cyl(similarity(), 0.5f, 1.0f, -2.0f, float(300 * kDeg), false);
    EXPECT_NEAR(cyl.area(), 4 * 300 * kDeg * 0.5 * 3, 1e-5 * cyl.area());
}

// Under non-uniform scales the world area is A_obj E[J] by quadrature; closed forms to compare with.
TEST(AnalyticArea, NonUniformScales) {
    // Oblate spheroid a = 2, c = 1: A = 2π a² (1 + (1 - e²)/e atanh e), e² = 1 - c²/a².
    SphereShape oblate(Transform::rotate(30, {1, 0, 0}) * Transform::scale(2, 2, 1), 1, -1, 1,
                       float(2 * kPiD), false);
    double e = std::sqrt(0.75);
    EXPECT_NEAR(oblate.area(), 2 * kPiD * 4 * (1 + (1 - e * e) / e * std::atanh(e)), 1e-5 * oblate.area());
    // Prolate spheroid a = 1, c = 2: A = 2π a² (1 + c/(a e) asin e).
    SphereShape prolate(Transform::scale(1, 1, 2), 1, -1, 1, float(2 * kPiD), false);
    EXPECT_NEAR(prolate.area(), 2 * kPiD * (1 + 2 / e * std::asin(e)), 1e-5 * prolate.area());
    // A disk's area scales by the 2D determinant: 2 x 3 here.
    DiskShape disk(Transform::scale(2, 3, 5), 0, 1, 0.5f, false, float(90 * kDeg));
    EXPECT_NEAR(disk.area(), 6 * kPiD / 4 * 0.75, 1e-5 * disk.area());
    // Elliptic cylinder, semi-axes 1 and 2, height 3: perimeter by Ramanujan's second formula (relative
    // error below 1e-7 for this ratio) times the height.
    CylinderShape cyl(Transform::scale(1, 2, 1.5f), 1, -1, 1, float(2 * kPiD), false);
    double a = 1, b = 2, h = (a - b) * (a - b) / ((a + b) * (a + b));
    double perimeter = kPiD * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)));
    EXPECT_NEAR(cyl.area(), perimeter * 3, 1e-5 * cyl.area());
}

// Object-space coordinates of a world point.
Point3f object_point(const AnalyticShape& s, Point3f p) { return s.world_from_object().inverse()(p); }
double phi_of(Point3f p) {
    double phi = std::atan2(double(p.y), double(p.x));
    return phi < 0 ? phi + 2 * kPiD : phi;
}

// Samples by area, checks each point lies on the partial surface, and chi-square tests the histogram over
// (a, φ) where `coord` gives a in [0, 1] (uniform when sampling is uniform by area).
template <class Coord, class OnSurface>
void expect_uniform(const AnalyticShape& shape, double phimax, Coord coord, OnSurface on_surface,
                    const char* what) {
    constexpr int na = 10, nphi = 12, n = 120000;
    std::vector<double> observed(na * nphi, 0), expected(na * nphi, double(n) / (na * nphi));
    PCG32 rng(11);
    int off_surface = 0;
    for (int i = 0; i < n; ++i) {
        AreaShapeSample s = shape.sample_area({rng.uniform_float(), rng.uniform_float()});
        EXPECT_NEAR(s.pdf.value, 1 / shape.area(), 1e-5f / shape.area());
        Point3f p = object_point(shape, s.p);
        double a = coord(p), phi = phi_of(p);
        // φ near 2π may read as near 0 after rounding.
        if (phi > phimax + 1e-4 && phi > 2 * kPiD - 1e-4) phi = 0;
        off_surface += !on_surface(p) || a < -1e-4 || a > 1 + 1e-4 || phi > phimax + 1e-4;
        int ia = std::clamp(int(a * na), 0, na - 1), ip = std::clamp(int(phi / phimax * nphi), 0, nphi - 1);
        observed[ia * nphi + ip] += 1;
    }
    EXPECT_EQ(off_surface, 0) << what;
    auto r = test::chi2_test(observed, expected);
    ::testing::Test::RecordProperty(what, fmt::format("chi2 p = {:.3f}", r.p_value));
    EXPECT_GT(r.p_value, 0.01) << what << " chi2 " << r.statistic << " dof " << r.dof;
}

TEST(AnalyticSampling, UniformByAreaOverThePartialSurface) {
    {
        const double zmin = -0.4, zmax = 0.9, phimax = 250 * kDeg;
        SphereShape s(similarity(), 1, float(zmin), float(zmax), float(phimax), false);
        expect_uniform(
            s, phimax, [&](Point3f p) { return (p.z - zmin) / (zmax - zmin); },
            [](Point3f p) { return std::abs(length(Vector3f(p)) - 1) < 1e-5f; }, "partial sphere");
    }
    {
        const double r = 1.5, ri = 0.5, phimax = 100 * kDeg;
        DiskShape d(similarity(), 0.2f, float(r), float(ri), false, float(phimax));
        expect_uniform(
            d, phimax, [&](Point3f p) { return (p.x * p.x + p.y * p.y - ri * ri) / (r * r - ri * ri); },
            [](Point3f p) { return std::abs(p.z - 0.2f) < 1e-5f; }, "annular sector");
        DiskShape full(similarity(), 0.2f, float(r), float(ri), false);
        expect_uniform(
            full, 2 * kPiD, [&](Point3f p) { return (p.x * p.x + p.y * p.y - ri * ri) / (r * r - ri * ri); },
            [](Point3f p) { return std::abs(p.z - 0.2f) < 1e-5f; }, "annulus");
    }
    {
        const double zmin = -1, zmax = 0.5, phimax = 330 * kDeg;
        CylinderShape c(similarity(), 0.7f, float(zmin), float(zmax), float(phimax), false);
        expect_uniform(
            c, phimax, [&](Point3f p) { return (p.z - zmin) / (zmax - zmin); },
            [](Point3f p) { return std::abs(std::hypot(p.x, p.y) - 0.7f) < 1e-5f; }, "partial cylinder");
    }
}

// Under a non-uniform scale the samples are not uniform, but their pdf is exact: E[1/pdf] = area, and
// sample_area()'s pdf is area_pdf() at the same point.
TEST(AnalyticSampling, NonUniformScaleKeepsAnExactPdf) {
    std::unique_ptr<AnalyticShape> shapes[] = {
        std::make_unique<SphereShape>(non_uniform(), 1.0f, -0.6f, 1.0f, float(300 * kDeg), false),
        std::make_unique<CylinderShape>(non_uniform(), 1.0f, -1.0f, 1.0f, float(200 * kDeg), false)};
    for (auto& shape : shapes) {
        MeanAccumulator inv_pdf;
        PCG32 rng(3);
        for (int i = 0; i < 100000; ++i) {
            AreaShapeSample s = shape->sample_area({rng.uniform_float(), rng.uniform_float()});
            inv_pdf.add(1 / double(s.pdf.value));
            if (i < 1000) {
                EXPECT_NEAR(shape->area_pdf(s.p).value, s.pdf.value, 1e-4f * s.pdf.value);
            }
        }
        EXPECT_NEAR(inv_pdf.mean, shape->area(), 4 * inv_pdf.std_error()) << "SE " << inv_pdf.std_error();
        EXPECT_GT(inv_pdf.std_error(), 0) << "not uniform in the world";
    }
}

// For a receiver p: sample()'s pdf equals pdf() at the sampled point, and the integral over directions
// of pdf() summed over every crossing of the shape (a partial shape can be crossed twice; the cone
// sampler of a whole sphere covers only the near side) is 1. Directions are drawn uniformly in a cone
// around the shape's bounding sphere (or the whole sphere when p is inside it).
void expect_solid_angle_pdf(const AnalyticShape& shape, Point3f p, bool near_side_only, const char* what) {
    ShapeSampleContext ctx{p, {}, {}};
    PCG32 rng(5);
    int mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        auto s = shape.sample(ctx, {rng.uniform_float(), rng.uniform_float()});
        if (!s) continue;
        Vector3f wi = normalize(s->p - p);
        EXPECT_LT(length(s->wi - wi), 1e-6f) << what << ": the sample's direction is the one to its point";
        float pdf = shape.pdf(ctx, wi, s->p, s->n).value;
        mismatches += !(std::abs(pdf - s->pdf.value) <= 2e-3f * s->pdf.value);
    }
    EXPECT_LE(mismatches, 2) << what << ": sample() and pdf() disagree";

    Point3f c;
    float radius;
    shape.bounds().bounding_sphere(&c, &radius);
    float d = distance(p, c);
    float cos_max = d > radius ? std::sqrt(1 - radius * radius / (d * d)) : -1;
    Frame frame = Frame::from_z(d > 0 ? normalize(c - p) : Vector3f{0, 0, 1});
    double cone = 2 * kPiD * (1 - cos_max);
    MeanAccumulator integral;
    for (int i = 0; i < 400000; ++i) {
        Vector3f w = frame.to_world(sample_uniform_cone({rng.uniform_float(), rng.uniform_float()}, cos_max));
        Crossing cr[2];
        int n = shape.crossings(Ray{p, w, kInfinity}, 0, kInfinity, cr);
        if (near_side_only) n = std::min(n, 1);
        double sum = 0;
        for (int k = 0; k < n; ++k) {
            SurfaceHit h = shape.alpha_point(cr[k]);
            sum += shape.pdf(ctx, w, h.p, h.n).value;
        }
        integral.add(sum * cone);
    }
    ::testing::Test::RecordProperty(what,
                                    fmt::format("{:.5f} +- {:.2g}", integral.mean, integral.std_error()));
    EXPECT_NEAR(integral.mean, 1, 4 * integral.std_error() + 1e-4) << what << " SE " << integral.std_error();
}

TEST(AnalyticSampling, SolidAnglePdfMatchesAndIntegratesToOne) {
    SphereShape full(similarity(), 0.5f, -0.5f, 0.5f, float(2 * kPiD), false);
    ASSERT_TRUE(full.is_round());
    expect_solid_angle_pdf(full, {3, 0, 1}, true, "whole sphere from outside (cone)");
    expect_solid_angle_pdf(full, Point3f(full.center() + Vector3f{0.2f, 0.1f, 0}), false,
                           "whole sphere from inside");
    SphereShape partial(similarity(), 0.5f, -0.2f, 0.5f, float(230 * kDeg), false);
    expect_solid_angle_pdf(partial, {3, 0, 1}, false, "partial sphere from outside");
    SphereShape ellipsoid(non_uniform(), 1.0f, -1.0f, 1.0f, float(2 * kPiD), false);
    expect_solid_angle_pdf(ellipsoid, {4, 1, 2}, false, "ellipsoid");
    DiskShape half(non_uniform(), 0, 1, 0.2f, false, float(kPiD));
    expect_solid_angle_pdf(half, {2, -1, 2}, false, "half annulus");
    CylinderShape cyl(similarity(), 0.5f, -0.5f, 1, float(270 * kDeg), false);
    expect_solid_angle_pdf(cyl, {3, -1, 0}, false, "partial cylinder");
}

// A caller that does not read uv (an emitter without an image or alpha) gets the same point, error bound
// and normal as one that does, with uv left zero; one that does gets pbrt's (φ/φmax, θ) parameterisation.
TEST(AnalyticSampling, ConeSampleWithoutUvIsTheSamePoint) {
    for (bool flip : {false, true}) {
        SphereShape sphere(similarity(), 0.5f, -0.5f, 0.5f, float(2 * kPiD), flip);
        ASSERT_TRUE(sphere.is_round());
        PCG32 rng(7);
        int samples = 0;
        for (int i = 0; i < 2000; ++i) {
            ShapeSampleContext ctx{Point3f{3, 0, 1}, {}, {}};
            Point2f u{rng.uniform_float(), rng.uniform_float()};
            auto with = sphere.sample(ctx, u);
            ctx.uv_needed = false;
            auto without = sphere.sample(ctx, u);
            ASSERT_EQ(bool(with), bool(without));
            if (!with) continue;
            ++samples;
            EXPECT_EQ(with->p, without->p);
            EXPECT_EQ(with->p_error, without->p_error);
            EXPECT_EQ(with->n, without->n);
            EXPECT_EQ(with->pdf.value, without->pdf.value);
            EXPECT_EQ(without->uv, Point2f(0, 0));
            // The uv a caller asks for is the point's: z = r cos θ in object space, θ = π (1 - v) for the
            // whole sphere (θ(zmin) = π, θ(zmax) = 0).
            Point3f c = sphere.center();
            float cos_theta = dot(Vector3f(with->p - c) / sphere.world_radius(),
                                  normalize(Transform::rotate(70, {1, 1, 0})(Vector3f{0, 0, 1})));
            EXPECT_NEAR(std::cos(kPi * (1 - with->uv.y)), cos_theta, 2e-4f);
        }
        EXPECT_GT(samples, 1900);
    }
}

} // namespace
} // namespace illum
