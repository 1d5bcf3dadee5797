// The shading partials a hit completes on demand (geometry/shading_partials.h), against pbrt-v4's
// definitions: the position's derivatives along the parameterisation, checked by finite differences of
// the surface point, and the normal's derivatives.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/geometry/cylinder.h"
#include "illum/geometry/disk.h"
#include "illum/geometry/sphere.h"
#include "illum/geometry/triangle_mesh.h"

namespace illum {
namespace {

void expect_vec(Vector3f a, Vector3f b, float tol, const char* what) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

TEST(ShadingPartials, TriangleSolvesTheUvParameterisation) {
    TriangleMesh m;
    m.p = {{0, 0, 0}, {2, 0.5f, 0.1f}, {0.3f, 1.5f, -0.2f}};
    m.uv = {{0.1f, 0.2f}, {0.9f, 0.3f}, {0.2f, 0.8f}};
    m.indices = {0, 1, 2};
    m.finalize();
    ShadingPartials s = m.shading_partials(0, {0.3f, 0.3f, 0});
    // p_i - p_0 = ∂p/∂u (u_i - u_0) + ∂p/∂v (v_i - v_0): the parameterisation is affine on a triangle.
    for (int i : {1, 2}) {
        Vector2f duv = m.uv[i] - m.uv[0];
        expect_vec(s.dpdu * duv.x + s.dpdv * duv.y, m.p[i] - m.p[0], 1e-5f, "edge");
    }
    expect_vec(Vector3f(s.dndu), {}, 0, "no normals: flat");
    // Without uv, pbrt-v4's (0,0), (1,0), (1,1): ∂p/∂u = p1 - p0, ∂p/∂v = p2 - p1.
    m.uv.clear();
    s = m.shading_partials(0, {0.2f, 0.5f, 0});
    expect_vec(s.dpdu, m.p[1] - m.p[0], 1e-5f, "default uv dpdu");
    expect_vec(s.dpdv, m.p[2] - m.p[1], 1e-5f, "default uv dpdv");
    // Degenerate uv: an orthonormal frame around the face normal.
    m.uv = {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};
    s = m.shading_partials(0, {0.2f, 0.5f, 0});
    EXPECT_NEAR(length(s.dpdu), 1, 1e-5f);
    EXPECT_NEAR(dot(s.dpdu, Vector3f(m.geometric_normal(0))), 0, 1e-5f);
    EXPECT_NEAR(dot(s.dpdv, Vector3f(m.geometric_normal(0))), 0, 1e-5f);
}

TEST(ShadingPartials, TriangleWithNormalsFollowsTheShadingNormal) {
    TriangleMesh m;
    m.p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.uv = {{0, 0}, {1, 0}, {0, 1}};
    m.n = {normalize(Normal3f(-0.2f, 0, 1)), normalize(Normal3f(0.3f, 0, 1)),
           normalize(Normal3f(0, 0.4f, 1))};
    m.indices = {0, 1, 2};
    m.finalize();
    float b1 = 0.3f, b2 = 0.2f;
    ShadingPartials s = m.shading_partials(0, {b1, b2, 0});
    Normal3f ns = normalize(m.n[0] * (1 - b1 - b2) + m.n[1] * b1 + m.n[2] * b2);
    // ∂p/∂u orthogonal to ns, ∂p/∂v = ns × ∂p/∂u.
    EXPECT_NEAR(dot(s.dpdu, Vector3f(ns)), 0, 1e-6f);
    expect_vec(s.dpdv, cross(Vector3f(ns), s.dpdu), 1e-6f, "bitangent");
    // u, v are x, y here: ∂n/∂u = n1 - n0, ∂n/∂v = n2 - n0 (the interpolated, unnormalised normal).
    expect_vec(Vector3f(s.dndu), Vector3f(m.n[1]) - Vector3f(m.n[0]), 1e-5f, "dndu");
    expect_vec(Vector3f(s.dndv), Vector3f(m.n[2]) - Vector3f(m.n[0]), 1e-5f, "dndv");
}

// An analytic shape's partials against the uv of hits a small step along ∂p/∂u and ∂p/∂v away (found by
// rays along `dir` through the stepped points, which lie on the surface to second order).
template <typename Shape>
void check_analytic(const Shape& shape, Point3f target, Vector3f dir, float curvature, const char* what) {
    auto hit_along = [&](Point3f t) {
        Ray ray{t - dir * 10, dir, kInfinity};
        Crossing c[2];
        EXPECT_GT(shape.crossings(ray, 0, kInfinity, c), 0) << what;
        SurfaceHit h;
        shape.fill_hit(float(c[0].t), ray, &h);
        h.complete_shading_partials();
        return h;
    };
    SurfaceHit h = hit_along(target);
    // n is along ∂p/∂u × ∂p/∂v (up to the orientation flip).
    Vector3f c = normalize(cross(h.dpdu, h.dpdv));
    EXPECT_NEAR(std::abs(dot(c, Vector3f(h.n))), 1, 1e-5f) << what;
    // A small step ε along ∂p/∂u moves uv by about (ε, 0) (to first order), and ∂p/∂v likewise.
    const float eps = 1e-3f;
    for (int k = 0; k < 2; ++k) {
        Vector3f t = k == 0 ? h.dpdu : h.dpdv;
        SurfaceHit g = hit_along(h.p + t * eps);
        float du = g.uv.x - h.uv.x, dv = g.uv.y - h.uv.y;
        EXPECT_NEAR(k == 0 ? du : dv, eps, eps * 0.02f) << what << " along " << k;
        EXPECT_NEAR(k == 0 ? dv : du, 0, eps * 0.02f) << what << " along " << k;
    }
    // ∂n/∂u = κ ∂p/∂u on these umbilic or flat directions (κ = 1/r for the sphere, 0 for the disk).
    expect_vec(Vector3f(h.dndu), h.dpdu * curvature, 1e-5f, what);
}

TEST(ShadingPartials, AnalyticShapesMatchTheirParameterisation) {
    SphereShape sphere(Transform::translate({1, 2, 3}), 2, -2, 2, 2 * kPi, false);
    check_analytic(sphere, {1.5f, 2.7f, 3.4f}, normalize(Vector3f(-1, -0.5f, -0.3f)), 0.5f, "sphere");
    DiskShape disk(Transform::translate({0, 0, 1}), 0, 2, 0.5f, false);
    check_analytic(disk, {0.8f, 0.6f, 1}, {0, 0, -1}, 0, "disk");
    CylinderShape cyl(Transform::translate({0, 0, 0}), 1.5f, -1, 1, 2 * kPi, false);
    Ray ray{{5, 0.5f, 0.2f}, {-1, 0, 0}, kInfinity};
    Crossing c[2];
    ASSERT_GT(cyl.crossings(ray, 0, kInfinity, c), 0);
    SurfaceHit h;
    cyl.fill_hit(float(c[0].t), ray, &h);
    h.complete_shading_partials();
    expect_vec(h.dpdv, {0, 0, 2}, 1e-6f, "cylinder dpdv");
    expect_vec(Vector3f(h.dndu), h.dpdu * (1 / 1.5f), 1e-5f, "cylinder dndu");
}

} // namespace
} // namespace illum
