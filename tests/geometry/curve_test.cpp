// pbrt-v4's "curve" shape on Embree's native curves: silhouette areas against the analytic width (coverage
// counts of parallel rays within their binomial error), a Bézier's hit u, v and t against the curve, the
// B-spline and quadratic conversions, and the parameter checks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/curves.h"
#include "illum/param/param_set.h"
#include "illum/util/error.h"
#include "param_support.h"

namespace illum {
namespace {

using test::floats;

Param text(const std::string& name, const std::string& value) {
    Param p;
    p.name = name;
    p.type = ParamType::String;
    p.strings = {value};
    return p;
}

ShapeDesc curve_desc(std::vector<Param> params, const Transform& m = Transform()) {
    ShapeDesc s;
    s.type = "curve";
    s.world_from_object = m;
    for (Param& p : params) s.params.add(std::move(p));
    return s;
}

std::unique_ptr<Curves> make(std::vector<Param> params, const Transform& m = Transform()) {
    Diagnostics diag;
    return create_curves(curve_desc(std::move(params), m), diag);
}

// The fraction of `n` parallel rays along `dir`, through uniform random points of the rectangle
// [x0, x1] x [y0, y1] at z = 10 (dir's z negative), that hit; and the rectangle's area.
struct Coverage {
    double hits, n, area;
};
Coverage coverage(const Accelerator& acc, Vector3f dir, float x0, float x1, float y0, float y1, int n,
                  std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> U(0, 1);
    double hits = 0;
    for (int i = 0; i < n; ++i) {
        Point3f on_plane(x0 + (x1 - x0) * U(rng), y0 + (y1 - y0) * U(rng), 0);
        Ray ray{on_plane - dir * 20, dir, kInfinity};
        SurfaceHit hit;
        hits += acc.intersect(ray, &hit);
    }
    return {hits, double(n), double(x1 - x0) * (y1 - y0)};
}

// The covered area against `expected`, within 4.5 binomial standard errors.
void expect_area(const Coverage& c, double expected, const char* what) {
    double p = c.hits / c.n, se = std::sqrt(p * (1 - p) / c.n) * c.area;
    EXPECT_NEAR(p * c.area, expected, 4.5 * se) << what << " (standard error " << se << ")";
}

// A straight flat curve of length L and width w seen along its normal covers w·L; with widths w0 → w1 a
// trapezoid of area L (w0 + w1) / 2. Seen from 0.9 rad off the normal (tilted about the curve's axis) the
// ray-facing ribbon still shows its whole width w across the rays, so on the plane z = 0, where the rays
// are sampled, it covers the area w·L / cos 0.9.
TEST(Curve, FlatSilhouetteMatchesItsWidth) {
    const float L = 4, w = 0.3f;
    for (auto [w0, w1] : {std::pair{w, w}, std::pair{0.1f, 0.5f}}) {
        Accelerator acc;
        acc.add_curves(make({floats("P", {-2, 0, 0, -0.7, 0, 0, 0.6, 0, 0, 2, 0, 0}, ParamType::Point3),
                             floats("width0", {w0}), floats("width1", {w1})}),
                       nullptr);
        acc.commit();
        double expected = L * 0.5 * (w0 + w1);
        expect_area(coverage(acc, {0, 0, -1}, -2.5f, 2.5f, -0.5f, 0.5f, 200000, 1), expected,
                    "flat, from above");
        Vector3f tilted = normalize(Vector3f(0, std::sin(0.9f), -std::cos(0.9f)));
        expect_area(coverage(acc, tilted, -2.5f, 2.5f, -0.5f, 0.5f, 200000, 2), expected / std::cos(0.9),
                    "flat, tilted view");
    }
}

// A ribbon of normal +z lying along x: seen from above it covers w·L, seen at angle θ from its normal its
// projection on the plane z = 0 is still the rectangle w × L (the ribbon lies in that plane).
TEST(Curve, RibbonLiesInThePlaneOfItsNormal) {
    const float L = 4, w = 0.4f;
    Accelerator acc;
    acc.add_curves(make({floats("P", {-2, 0, 0, -0.7, 0, 0, 0.6, 0, 0, 2, 0, 0}, ParamType::Point3),
                         floats("width", {w}), text("type", "ribbon"),
                         floats("N", {0, 0, 1, 0, 0, 1}, ParamType::Normal)}),
                   nullptr);
    acc.commit();
    expect_area(coverage(acc, {0, 0, -1}, -2.5f, 2.5f, -0.5f, 0.5f, 200000, 3), L * w, "ribbon, face on");
    Vector3f tilted = normalize(Vector3f(0, std::sin(1.0f), -std::cos(1.0f)));
    expect_area(coverage(acc, tilted, -2.5f, 2.5f, -0.5f, 0.5f, 200000, 4), L * w, "ribbon, tilted");
    // Seen edge-on (rays along y, in the ribbon's plane, through points of the plane y = -5) it vanishes,
    // where a ray-facing ribbon would show its width.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<float> U(-1, 1);
    int edge_hits = 0;
    for (int i = 0; i < 20000; ++i) {
        SurfaceHit hit;
        edge_hits += acc.intersect({{2.5f * U(rng), -5, 0.5f * U(rng)}, {0, 1, 0}, kInfinity}, &hit);
    }
    EXPECT_LT(edge_hits, 20); // the rays within |z| < 1e-3 of its plane at most
}

// Rays aimed at known points of a curved Bézier: the hit's u is the curve parameter of the aimed point, v
// its offset across the width (v = 1/2 + s/w for an offset s along d × dp/du), t the distance to it, and
// dp/du the curve's derivative there; for "cylinder" the normal turns from facing along the ray at the
// axis to perpendicular to it at the edges. Embree intersects the curve as ray-facing quads, as many per
// segment as pbrt-v4's refinement criterion asks for (an accuracy ε = width/20, curves.h), so positions are
// within ε: t within ε, u within ε / |dp/du| (twice that, for the quads' chords), v within ε / w.
TEST(Curve, BezierHitsGiveTheCurveParameterAndOffset) {
    const std::array<Point3f, 4> c = {Point3f(-2, 0, 0), Point3f(-1, 1.5f, 0.3f), Point3f(1, -1, -0.2f),
                                      Point3f(2, 0.5f, 0)};
    const float w0 = 0.2f, w1 = 0.1f;
    for (const char* type : {"flat", "cylinder"}) {
        Accelerator acc;
        acc.add_curves(make({floats("P", {-2, 0, 0, -1, 1.5, 0.3, 1, -1, -0.2, 2, 0.5, 0}, ParamType::Point3),
                             floats("width0", {w0}), floats("width1", {w1}), text("type", type)}),
                       nullptr);
        acc.commit();
        const Vector3f d = normalize(Vector3f(0.1f, -0.2f, -1));
        for (float u : {0.1f, 0.35f, 0.5f, 0.8f})
            for (float s : {-0.8f, -0.3f, 0.0f, 0.45f, 0.9f}) { // offset as a fraction of the half width
                Vector3f dpdu;
                Point3f axis = bezier_point(c, u, &dpdu);
                float w = w0 + (w1 - w0) * u;
                Vector3f across = normalize(cross(d, dpdu));
                Point3f target = axis + across * (s * 0.5f * w);
                Ray ray{target - d * 10, d, kInfinity};
                SurfaceHit hit;
                ASSERT_TRUE(acc.intersect(ray, &hit)) << type << " u " << u << " s " << s;
                const float eps = w / 20;
                EXPECT_NEAR(hit.uv.x, u, 2 * eps / length(dpdu)) << type << " u " << u << " s " << s;
                EXPECT_NEAR(hit.uv.y, 0.5f + 0.5f * s, eps / w) << type << " u " << u << " s " << s;
                EXPECT_NEAR(hit.t, 10, eps) << type << " u " << u << " s " << s;
                EXPECT_GT(dot(normalize(hit.dpdu), normalize(dpdu)), 0.9999f);
                // |n·d| = |d⊥| (d's part across the curve) for flat; turned by (v - 1/2)·180° for cylinder.
                float cos_nd = std::abs(dot(Vector3f(hit.n), d));
                float d_perp = std::sqrt(1 - sqr(dot(d, normalize(dpdu))));
                float turn = std::string(type) == "flat" ? 1 : std::abs(std::cos((hit.uv.y - 0.5f) * kPi));
                EXPECT_NEAR(cos_nd, d_perp * turn, 2e-3f) << type << " u " << u << " s " << s;
            }
        // Beside the curve (offset beyond the half width) nothing is hit.
        Vector3f dpdu;
        Point3f axis = bezier_point(c, 0.5f, &dpdu);
        Point3f beside = axis + normalize(cross(d, dpdu)) * 0.6f * (w0 + w1);
        SurfaceHit hit;
        EXPECT_FALSE(acc.intersect({beside - d * 10, d, kInfinity}, &hit));
    }
}

// A uniform cubic B-spline becomes the Bézier segments with the same points; a quadratic Bézier is elevated
// without changing its curve.
TEST(Curve, BasisConversionsKeepTheCurve) {
    const std::vector<double> p = {0, 0, 0, 1, 2, 0, 3, 2, 1, 4, 0, 1, 6, 1, 0};
    auto bs = make({floats("P", p, ParamType::Point3), text("basis", "bspline")});
    ASSERT_EQ(bs->segment_count(), 2u);
    auto at = [&](int i) { return Point3f(float(p[3 * i]), float(p[3 * i + 1]), float(p[3 * i + 2])); };
    for (int seg = 0; seg < 2; ++seg)
        for (float t : {0.0f, 0.3f, 0.7f, 1.0f}) {
            // The uniform cubic B-spline basis.
            float b0 = (1 - t) * (1 - t) * (1 - t) / 6, b1 = (3 * t * t * t - 6 * t * t + 4) / 6,
                  b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, b3 = t * t * t / 6;
            Vector3f e = Vector3f(at(seg)) * b0 + Vector3f(at(seg + 1)) * b1 + Vector3f(at(seg + 2)) * b2 +
                         Vector3f(at(seg + 3)) * b3;
            Point3f got = bezier_point(bs->cp[std::size_t(seg)], t);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], e[k], 1e-5f) << seg << " " << t;
        }
    auto quad = make({floats("P", {0, 0, 0, 1, 2, 0, 2, 0, 1}, ParamType::Point3),
                      floats("degree", {2}, ParamType::Integer)});
    ASSERT_EQ(quad->segment_count(), 1u);
    for (float t : {0.0f, 0.25f, 0.6f, 1.0f}) {
        Vector3f e = Vector3f(0, 0, 0) * ((1 - t) * (1 - t)) + Vector3f(1, 2, 0) * (2 * t * (1 - t)) +
                     Vector3f(2, 0, 1) * (t * t);
        Point3f got = bezier_point(quad->cp[0], t);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], e[k], 1e-5f) << t;
    }
    // Widths: linear over the segments by index, as pbrt-v4 assigns them.
    auto two = make({floats("P", p, ParamType::Point3), text("basis", "bspline"), floats("width0", {1}),
                     floats("width1", {3})});
    EXPECT_FLOAT_EQ(two->width[0][0], 1);
    EXPECT_FLOAT_EQ(two->width[0][1], 2);
    EXPECT_FLOAT_EQ(two->width[1][1], 3);
    // Under a uniform scale the width scales too.
    auto scaled =
        make({floats("P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, ParamType::Point3), floats("width", {0.5})},
             Transform::scale(2, 2, 2));
    EXPECT_FLOAT_EQ(scaled->width[0][0], 1);
}

TEST(Curve, RejectsMalformedParameters) {
    const std::vector<double> p4 = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
    EXPECT_THROW(make({floats("P", {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0}, ParamType::Point3)}),
                 Error);
    EXPECT_THROW(make({floats("P", p4, ParamType::Point3), floats("degree", {4}, ParamType::Integer)}),
                 Error);
    EXPECT_THROW(make({floats("P", p4, ParamType::Point3), text("basis", "hermite")}), Error);
    EXPECT_THROW(make({floats("P", p4, ParamType::Point3), text("type", "tube")}), Error);
    EXPECT_THROW(make({floats("P", p4, ParamType::Point3), text("type", "ribbon")}), Error); // no N
    EXPECT_THROW(make({floats("P", p4, ParamType::Point3), floats("width", {-1})}), Error);
    EXPECT_NO_THROW(
        make({floats("P", p4, ParamType::Point3), floats("splitdepth", {5}, ParamType::Integer)}));
}

} // namespace
} // namespace illum
