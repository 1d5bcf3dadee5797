// Ray intersection of pbrt's analytic shapes through the accelerator (Embree user geometry) against
// closed forms: each ray is chosen in object space, where its hits are known exactly, and carried into
// the world by a transform with rotation, translation and non-uniform scale (the ray parameter t is the
// same in both spaces). Then the robustness of spawned rays: no re-hit of the surface just left.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/cylinder.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/sphere.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

constexpr double kDeg = kPiD / 180;

// Rotation, non-uniform scale and translation (no handedness swap).
Transform skewed() {
    return Transform::translate({0.5f, -1, 2}) * Transform::rotate(40, {1, 2, 3}) *
           Transform::scale(1.5f, 0.7f, 1.2f);
}

struct Expected {
    double t;
    Point3f p_obj;
    Normal3f n_obj; // outward, object space
    Point2f uv;
};

// Traces the object-space ray (o, d) carried to the world by m and checks the hit against e.
void expect_hit(const Accelerator& acc, const Transform& m, Point3f o, Vector3f d, const Expected& e,
                bool flipped = false) {
    Ray ray{m(o), m(d), kInfinity};
    SurfaceHit hit;
    ASSERT_TRUE(acc.intersect(ray, &hit)) << "ray from " << o.x << " " << o.y << " " << o.z;
    EXPECT_NEAR(hit.t, e.t, 1e-5 * e.t);
    Point3f pw = m(e.p_obj);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(hit.p[i], pw[i], 1e-5f * (1 + std::abs(pw[i])));
        // The true point lies within the reported error bound (which is small, not a magic epsilon).
        EXPECT_LE(std::abs(hit.p[i] - pw[i]), hit.p_error[i] + 4e-7f * (1 + std::abs(pw[i])));
        EXPECT_LT(hit.p_error[i], 1e-5f * (1 + std::abs(pw[i])));
    }
    Normal3f n = normalize(m(e.n_obj));
    if (flipped) n = -n;
    EXPECT_GT(dot(hit.n, Vector3f(n)), 0.99999f);
    EXPECT_NEAR(hit.uv.x, e.uv.x, 1e-5f);
    EXPECT_NEAR(hit.uv.y, e.uv.y, 1e-5f);
}

void expect_miss(const Accelerator& acc, const Transform& m, Point3f o, Vector3f d) {
    SurfaceHit hit;
    EXPECT_FALSE(acc.intersect(Ray{m(o), m(d), kInfinity}, &hit))
        << "ray from " << o.x << " " << o.y << " " << o.z;
    EXPECT_FALSE(acc.occluded(Ray{m(o), m(d), kInfinity}));
}

// Sphere r = 1, zmax = 0.5, φmax = 270°: a ray down through the clipped cap hits the far (lower) side.
TEST(AnalyticIntersection, PartialSphereFarSideThroughClippedCap) {
    Transform m = skewed();
    Accelerator acc;
    acc.add_shape(std::make_unique<SphereShape>(m, 1.0f, -1.0f, 0.5f, float(270 * kDeg), false), nullptr,
                  nullptr);
    acc.commit();
    // Near root at z = +√0.75 (above zmax: clipped), far root at z = -√0.75, t = 2 + √0.75.
    double zc = std::sqrt(0.75), theta = std::acos(-zc), theta_min = kPiD, theta_max = std::acos(0.5);
    Expected e{
        2 + zc,
        {0.3f, 0.4f, float(-zc)},
        {0.3f, 0.4f, float(-zc)},
        {float(std::atan2(0.4, 0.3) / (270 * kDeg)), float((theta - theta_min) / (theta_max - theta_min))}};
    expect_hit(acc, m, {0.3f, 0.4f, 2}, {0, 0, -1}, e);
    EXPECT_NEAR(e.uv.y, 0.25f, 1e-6f); // (5π/6 - π) / (π/3 - π)
    // The same ray at φ = 360° - 53° (outside φmax) misses both roots.
    expect_miss(acc, m, {0.3f, -0.4f, 2}, {0, 0, -1});
    // From below, the near root (lower side, φ inside) is hit first.
    expect_hit(acc, m, {0.3f, 0.4f, -2}, {0, 0, 1}, {2 - zc, e.p_obj, e.n_obj, e.uv});
}

// The same sphere whole, under a non-uniform scale: an ellipsoid, exact (no mean-scale approximation).
TEST(AnalyticIntersection, NonUniformlyScaledSphereIsAnEllipsoid) {
    Transform m = skewed();
    Accelerator acc;
    acc.add_shape(std::make_unique<SphereShape>(m, 2.0f, -2.0f, 2.0f, float(2 * kPiD), false), nullptr,
                  nullptr);
    acc.commit();
    // Object ray along +x at y = 1.2: hits x = -1.6 at t = 3 - 1.6.
    double phi = std::atan2(1.2, -1.6), theta = kPiD / 2;
    expect_hit(
        acc, m, {-3, 1.2f, 0}, {1, 0, 0},
        {1.4, {-1.6f, 1.2f, 0}, {-0.8f, 0.6f, 0}, {float(phi / (2 * kPiD)), float((theta - kPiD) / -kPiD)}});
}

// Disk: radius 1, inner radius 0.25, height 0.5, φmax = 90°.
TEST(AnalyticIntersection, DiskWithPhimax) {
    Transform m = skewed();
    Accelerator acc;
    acc.add_shape(std::make_unique<DiskShape>(m, 0.5f, 1.0f, 0.25f, false, float(90 * kDeg)), nullptr,
                  nullptr);
    acc.commit();
    expect_hit(
        acc, m, {0.3f, 0.4f, 2}, {0, 0, -1},
        {1.5, {0.3f, 0.4f, 0.5f}, {0, 0, 1}, {float(std::atan2(0.4, 0.3) / (kPiD / 2)), float(0.5 / 0.75)}});
    expect_miss(acc, m, {-0.3f, 0.4f, 2}, {0, 0, -1}); // φ = 127° > 90°
    expect_miss(acc, m, {0.1f, 0.1f, 2}, {0, 0, -1});  // inside the inner radius
    expect_miss(acc, m, {0.8f, 0.8f, 2}, {0, 0, -1});  // outside the radius
}

// Cylinder: radius 1, z in [-1, 2], φmax = 180° (the half y >= 0).
TEST(AnalyticIntersection, CylinderWithPhimax) {
    Transform m = skewed();
    Accelerator acc;
    acc.add_shape(std::make_unique<CylinderShape>(m, 1.0f, 2.0f, -1.0f, float(kPiD), false), nullptr,
                  nullptr);
    acc.commit();
    double phi = std::atan2(0.6, -0.8);
    expect_hit(acc, m, {-3, 0.6f, 0.5f}, {1, 0, 0},
               {2.2, {-0.8f, 0.6f, 0.5f}, {-0.8f, 0.6f, 0}, {float(phi / kPiD), 0.5f}});
    expect_miss(acc, m, {-3, -0.6f, 0.5f}, {1, 0, 0}); // both roots at y < 0
    expect_miss(acc, m, {-3, 0.6f, 2.5f}, {1, 0, 0});  // above zmax
    // Through the missing half to the inside of the far wall at (0, 1): t = 4, outward normal +y.
    expect_hit(acc, m, {0, -3, 0.5f}, {0, 1, 0}, {4, {0, 1, 0.5f}, {0, 1, 0}, {0.5f, 0.5f}});
}

// ReverseOrientation flips the normal; a handedness-swapping transform flips it too (pbrt-v4).
TEST(AnalyticIntersection, OrientationFlips) {
    Transform mirror = Transform::scale(-1, 1, 1);
    Accelerator acc;
    acc.add_shape(std::make_unique<CylinderShape>(Transform(), 1.0f, -1, 1, float(2 * kPiD), true), nullptr,
                  nullptr);
    acc.commit();
    expect_hit(acc, Transform(), {-3, 0, 0}, {1, 0, 0}, {2, {-1, 0, 0}, {-1, 0, 0}, {0.5f, 0.5f}}, true);
    Accelerator acc2;
    acc2.add_shape(std::make_unique<DiskShape>(mirror, 0, 1, 0, mirror.swaps_handedness()), nullptr, nullptr);
    acc2.commit();
    SurfaceHit hit;
    ASSERT_TRUE(acc2.intersect(Ray{{0.2f, 0.1f, 1}, {0, 0, -1}}, &hit));
    EXPECT_LT(hit.n.z, -0.9999f);
}

// Embree's native sphere (kept for bench/shape_bench.cpp) and the user geometry agree on a round sphere.
TEST(AnalyticIntersection, NativeAndUserGeometrySpheresAgree) {
    Transform m =
        Transform::translate({3, 1, -2}) * Transform::rotate(20, {0, 0, 1}) * Transform::scale(2, 2, 2);
    Accelerator native, user;
    native.add_shape(std::make_unique<SphereShape>(m, 0.7f, -0.7f, 0.7f, float(2 * kPiD), false), nullptr,
                     nullptr, true);
    user.add_shape(std::make_unique<SphereShape>(m, 0.7f, -0.7f, 0.7f, float(2 * kPiD), false), nullptr,
                   nullptr);
    native.commit();
    user.commit();
    PCG32 rng(9);
    int differ = 0, hits = 0;
    for (int i = 0; i < 10000; ++i) {
        Point3f o{3 + 4 * (rng.uniform_float() - 0.5f), 1 + 4 * (rng.uniform_float() - 0.5f),
                  -2 + 4 * (rng.uniform_float() - 0.5f)};
        Ray ray{o, sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}), kInfinity};
        SurfaceHit a, b;
        bool ha = native.intersect(ray, &a), hb = user.intersect(ray, &b);
        hits += hb;
        if (ha != hb) {
            // Only grazing rays may disagree.
            differ += std::abs(dot((ha ? a : b).n, ray.d)) > 1e-3f;
            continue;
        }
        if (ha) differ += std::abs(a.t - b.t) > 1e-4f * (1 + b.t) || dot(a.n, b.n) < 0.9999f;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_EQ(differ, 0);
}

// Spawned rays never re-hit the surface they leave: from points on each shape (far from the origin,
// under a non-uniform scale), rays to the outside of a convex surface (or any ray off a disk) must miss
// it, and rays to the inside of a sphere or cylinder must reach the opposite wall, not the start.
TEST(AnalyticIntersection, SpawnedRaysDoNotSelfIntersect) {
    Transform m = Transform::translate({1000, -500, 250}) * Transform::rotate(25, {0, 1, 1}) *
                  Transform::scale(3, 1, 0.5f);
    struct Case {
        const char* name;
        std::unique_ptr<AnalyticShape> shape;
        bool concave_side = false; // a ray inwards may hit the far wall
        bool closed = false;       // ... and must
    };
    Case cases[] = {
        {"sphere", std::make_unique<SphereShape>(m, 1.0f, -1.0f, 1.0f, float(2 * kPiD), false), true},
        {"disk", std::make_unique<DiskShape>(m, 0.3f, 1.0f, 0.0f, false), false},
        {"cylinder", std::make_unique<CylinderShape>(m, 1.0f, -1.0f, 1.0f, float(2 * kPiD), false), true,
         false}};
    for (Case& c : cases) {
        const AnalyticShape* shape = c.shape.get();
        Accelerator acc;
        acc.add_shape(std::move(c.shape), nullptr, nullptr);
        acc.commit();
        PCG32 rng(7);
        int self_hits = 0, n = 20000;
        for (int i = 0; i < n; ++i) {
            AreaShapeSample s = shape->sample_area({rng.uniform_float(), rng.uniform_float()});
            Vector3f w = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
            bool outwards = dot(w, s.n) > 0;
            // A grazing ray inwards has a legitimately short chord: leave those out of the inside check.
            if (!outwards && c.concave_side && std::abs(dot(w, s.n)) < 0.05f) continue;
            Ray ray = spawn_ray(s.p, s.p_error, s.n, w);
            SurfaceHit hit;
            bool hits = acc.intersect(ray, &hit);
            if (outwards || !c.concave_side) {
                self_hits += hits;
            } else {
                // The far wall is at least ~ the chord length away; a hit near the start is acne. (A ray into
                // the open cylinder may leave through an end; one into the sphere may not.)
                self_hits += (hits && hit.t < 1e-3f) || (!hits && c.closed);
            }
            self_hits += acc.occluded(ray) != hits;
        }
        EXPECT_EQ(self_hits, 0) << c.name;
    }
}

// crossings() first tests the ray against the shape's world bounds (Embree calls a one-primitive user
// geometry for every ray): no ray that reaches the surface may be culled. Rays from random outside points
// aimed at random surface points (grazing ones near the silhouette included) of far-off, skewed shapes must
// all find a crossing at the point's distance; rays aimed past the bounds must find none.
TEST(AnalyticIntersection, BoundsCullingKeepsEveryCrossing) {
    Transform m = Transform::translate({1000, -500, 250}) * Transform::rotate(25, {0, 1, 1}) *
                  Transform::scale(3, 1, 0.5f);
    std::unique_ptr<AnalyticShape> shapes[] = {
        std::make_unique<SphereShape>(m, 1.0f, -1.0f, 1.0f, float(2 * kPiD), false),
        std::make_unique<SphereShape>(m, 1.0f, -0.3f, 0.8f, float(1.5 * kPiD), false),
        std::make_unique<DiskShape>(m, 0.3f, 1.0f, 0.0f, false),
        std::make_unique<CylinderShape>(m, 1.0f, -1.0f, 1.0f, float(2 * kPiD), false)};
    for (const auto& shape : shapes) {
        Bounds3f b = shape->bounds();
        Point3f c = b.center();
        float r = length(b.diagonal());
        PCG32 rng(11);
        int missed = 0, phantom = 0;
        for (int i = 0; i < 20000; ++i) {
            // (Points inside the parameter domain: one on a clip edge may be rounded off the clipped part.)
            AreaShapeSample s = shape->sample_area(
                {0.01f + 0.98f * rng.uniform_float(), 0.01f + 0.98f * rng.uniform_float()});
            Point3f o = c + sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}) * (2 * r);
            Vector3f d = s.p - o;
            // A grazing ray's crossing is ill-conditioned (the float-rounded target may lie just off the
            // surface): only rays at least 3° from the tangent plane are held to it.
            if (std::abs(dot(normalize(d), Vector3f(s.n))) < 0.05f) continue;
            Crossing x[2];
            int n = shape->crossings(Ray{o, d}, 0, 2, x);
            bool found = false;
            for (int k = 0; k < n; ++k) found = found || std::abs(x[k].t - 1) < 1e-4;
            missed += !found;
            // Aimed beside the bounds (perpendicular to the way to the centre, beyond the bounding radius).
            Vector3f to_c = c - o;
            Vector3f side = normalize(cross(to_c, Vector3f(0.3f, 0.5f, 0.8f)));
            phantom += shape->crossings(Ray{o, (c + side * (1.01f * r)) - o}, 0, kInfinity, x) != 0;
        }
        EXPECT_EQ(missed, 0);
        EXPECT_EQ(phantom, 0);
    }
}

} // namespace
} // namespace illum
