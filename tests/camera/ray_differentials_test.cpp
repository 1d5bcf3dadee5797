// Ray differentials (geometry/ray_differentials.h, camera/camera_differentials.cpp,
// render/texture_footprint.h): the cameras' against finite differences of neighbouring pixels' rays, the
// camera's approximation against the exact footprint, the least-squares ∂u/∂x..., and the differentials
// after a mirror and a refracting sphere against finite differences of the bounced rays.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/microfacet.h"
#include "illum/camera/camera.h"
#include "illum/camera/spherical_camera.h"
#include "illum/math/frame.h"
#include "illum/render/texture_footprint.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {
namespace {

void expect_near(Vector3f a, Vector3f b, float tol, const char* what) {
    EXPECT_NEAR(a.x, b.x, tol) << what;
    EXPECT_NEAR(a.y, b.y, tol) << what;
    EXPECT_NEAR(a.z, b.z, tol) << what;
}

// Where a ray meets the plane n·x = c.
Point3f on_plane(Point3f o, Vector3f d, Vector3f n, float c) {
    return o + d * ((c - dot(n, Vector3f(o))) / dot(n, d));
}

const Transform kWorldFromCamera = Transform::look_at({1, 2, -4}, {0.2f, 0, 0}, {0, 1, 0}).inverse();

TEST(CameraDifferentials, PerspectiveOffsetRaysAreTheNeighbouringPixels) {
    for (float lens : {0.0f, 0.2f}) {
        PerspectiveCamera cam(kWorldFromCamera, 64, 48, 50, lens, 3.5f);
        Point2f p{20.3f, 31.7f}, u{0.3f, 0.8f};
        RayDifferentials rd;
        auto cr = cam.generate_ray_differential(p, u, kDLineNm, &rd);
        ASSERT_TRUE(cr && rd.valid);
        auto rx = cam.generate_ray({p.x + 1, p.y}, u, kDLineNm),
             ry = cam.generate_ray({p.x, p.y + 1}, u, kDLineNm);
        expect_near(Vector3f(rd.rx_origin), Vector3f(rx->ray.o), 1e-5f, "rx origin");
        expect_near(rd.rx_direction, rx->ray.d, 1e-5f, "rx direction");
        expect_near(Vector3f(rd.ry_origin), Vector3f(ry->ray.o), 1e-5f, "ry origin");
        expect_near(rd.ry_direction, ry->ray.d, 1e-5f, "ry direction");
    }
}

TEST(CameraDifferentials, ScaledFootprintIsTheDerivativeOfTheHitPoint) {
    // On a tilted plane, the footprint of differentials scaled by s is s ∂p/∂x, ∂p/∂x from central
    // differences of the hit points of the rays through x ± ε.
    PerspectiveCamera cam(kWorldFromCamera, 64, 48, 50);
    Vector3f n = normalize(Vector3f(0.2f, 1, 0.3f));
    float c = -0.5f;
    Point2f p{40.5f, 30.5f};
    RayDifferentials rd;
    auto cr = cam.generate_ray_differential(p, {0.5f, 0.5f}, kDLineNm, &rd);
    const float s = 0.125f;
    rd.scale(cr->ray, s);
    SurfaceHit hit;
    hit.p = on_plane(cr->ray.o, cr->ray.d, n, c);
    hit.n = Normal3f(n);
    Vector3f dpdx, dpdy;
    ASSERT_TRUE(footprint_from_differentials(hit, rd, &dpdx, &dpdy));
    const float e = 0.01f;
    auto hit_at = [&](Point2f q) {
        auto r = cam.generate_ray(q, {0.5f, 0.5f}, kDLineNm);
        return on_plane(r->ray.o, r->ray.d, n, c);
    };
    Vector3f fx = (hit_at({p.x + e, p.y}) - hit_at({p.x - e, p.y})) / (2 * e);
    Vector3f fy = (hit_at({p.x, p.y + e}) - hit_at({p.x, p.y - e})) / (2 * e);
    // First order: the plane is tilted, so the 1/8-pixel offset ray's hit differs from the linearised
    // one by a second-order term of about 1% here.
    expect_near(dpdx, fx * s, 0.02f * length(fx) * s, "dpdx");
    expect_near(dpdy, fy * s, 0.02f * length(fy) * s, "dpdy");
}

TEST(CameraDifferentials, DefaultFiniteDifferencesOfTheSphericalCamera) {
    SphericalCamera cam(kWorldFromCamera, 64, 32, SphericalMapping::Equirectangular);
    Point2f p{21.3f, 9.6f};
    RayDifferentials rd;
    auto cr = cam.generate_ray_differential(p, {0.5f, 0.5f}, kDLineNm, &rd);
    ASSERT_TRUE(cr && rd.valid);
    const float e = 0.01f;
    auto dir = [&](Point2f q) { return cam.generate_ray(q, {0.5f, 0.5f}, kDLineNm)->ray.d; };
    Vector3f ddx = (dir({p.x + e, p.y}) - dir({p.x - e, p.y})) / (2 * e);
    Vector3f ddy = (dir({p.x, p.y + e}) - dir({p.x, p.y - e})) / (2 * e);
    expect_near(rd.rx_direction - cr->ray.d, ddx, 2e-3f * length(ddx), "x");
    expect_near(rd.ry_direction - cr->ray.d, ddy, 2e-3f * length(ddy), "y");
}

TEST(CameraDifferentials, ApproximationMatchesTheFootprintWhereTheDifferentialsAreSmallest) {
    // Orthographic: every ray's differentials are the same, so the approximation is exact on the camera's
    // axis (elsewhere pbrt-v4's construction turns them about the direction from the camera to the point).
    OrthographicCamera ortho(kWorldFromCamera, 64, 48);
    ortho.init_differentials(kWorldFromCamera, 64, 48);
    Vector3f n = normalize(Vector3f(0.2f, 1, 0.3f));
    for (Camera* cam : {static_cast<Camera*>(&ortho)}) {
        RayDifferentials rd;
        auto cr = cam->generate_ray_differential({32, 24}, {0.5f, 0.5f}, kDLineNm, &rd);
        SurfaceHit hit;
        hit.p = on_plane(cr->ray.o, cr->ray.d, n, -0.5f);
        hit.n = Normal3f(n);
        Vector3f dpdx, dpdy, ax, ay;
        ASSERT_TRUE(footprint_from_differentials(hit, rd, &dpdx, &dpdy));
        cam->approximate_dp_dxy(hit.p, hit.n, 1, &ax, &ay);
        expect_near(ax, dpdx, 1e-4f, "ortho x");
        expect_near(ay, dpdy, 1e-4f, "ortho y");
    }
    // Perspective: the smallest angular step lies at the film's corner; at the corner ray the
    // approximation is the footprint of the true differentials, to first order (a plane facing the ray).
    PerspectiveCamera persp(kWorldFromCamera, 64, 64, 30);
    persp.init_differentials(kWorldFromCamera, 64, 64);
    RayDifferentials rd;
    auto cr = persp.generate_ray_differential({0.0f, 0.0f}, {0.5f, 0.5f}, kDLineNm, &rd);
    Vector3f d = normalize(cr->ray.d);
    SurfaceHit hit;
    hit.p = cr->ray.o + d * 5;
    hit.n = Normal3f(-d);
    Vector3f dpdx, dpdy, ax, ay;
    ASSERT_TRUE(footprint_from_differentials(hit, rd, &dpdx, &dpdy));
    persp.approximate_dp_dxy(hit.p, hit.n, 1, &ax, &ay);
    EXPECT_NEAR(length(ax), length(dpdx), 0.01f * length(dpdx));
    EXPECT_NEAR(length(ay), length(dpdy), 0.01f * length(dpdy));
    // Both in the plane of the hit.
    EXPECT_NEAR(dot(ax, Vector3f(hit.n)), 0, 1e-5f);
    // Scaled as asked.
    Vector3f hx, hy;
    persp.approximate_dp_dxy(hit.p, hit.n, 0.25f, &hx, &hy);
    expect_near(hx, ax * 0.25f, 1e-6f, "scale");
}

TEST(TextureFootprint, UvDerivativesSolveTheLeastSquaresProblem) {
    TextureEvalContext c;
    // ∂p/∂x = 0.5 ∂p/∂u - 2 ∂p/∂v exactly (the residual is 0), ∂p/∂y with a component off the plane.
    Vector3f dpdu(2, 0.5f, 0), dpdv(0.3f, 3, 0);
    set_uv_derivatives(c, dpdu * 0.5f - dpdv * 2, dpdu * 0.25f + dpdv * 1.5f + Vector3f(0, 0, 7), dpdu, dpdv);
    EXPECT_NEAR(c.dudx, 0.5f, 1e-5f);
    EXPECT_NEAR(c.dvdx, -2.0f, 1e-5f);
    EXPECT_NEAR(c.dudy, 0.25f, 1e-5f);
    EXPECT_NEAR(c.dvdy, 1.5f, 1e-5f);
    // A degenerate parameterisation gives zeros, not infinities.
    set_uv_derivatives(c, {1, 0, 0}, {0, 1, 0}, dpdu, dpdu * 2);
    EXPECT_EQ(c.dudx, 0);
    EXPECT_EQ(c.dvdy, 0);
}

// A camera looking at a unit sphere: the differentials after a mirror reflection or a refraction on it
// against central differences of the bounced rays of the neighbouring film positions.
class SpecularDifferentials : public ::testing::Test {
protected:
    void SetUp() override {
        SceneDesc desc = parse_pbrt_string(R"(
            LookAt 0.3 0.5 4  0 0 0  0 1 0
            Camera "perspective" "float fov" [30]
            Film "rgb" "integer xresolution" [64] "integer yresolution" [64]
            WorldBegin
            AttributeBegin
              Translate 0.1 -0.05 0
              Shape "sphere" "float radius" [1]
            AttributeEnd
        )",
                                           "<test>", ".");
        scene_ = build_scene(desc);
    }

    struct Bounce {
        SurfaceHit hit;
        Vector3f wi;
        float etap = 1;
    };
    // The hit of the ray through film point p and the direction it leaves in.
    Bounce bounce(Point2f p, bool reflect_it, RayDifferentials* rd = nullptr) const {
        Bounce b;
        RayDifferentials d;
        auto cr = scene_->camera->generate_ray_differential(p, {0.5f, 0.5f}, kDLineNm, &d);
        EXPECT_TRUE(scene_->intersect(cr->ray, &b.hit));
        if (rd) {
            d.scale(cr->ray, kScale);
            compute_footprint(b.hit, d, *scene_, 64);
        }
        if (reflect_it) {
            b.wi = reflect(b.hit.wo, Vector3f(b.hit.ns));
        } else {
            EXPECT_TRUE(refract(b.hit.wo, Vector3f(b.hit.ns), kEta, &b.etap, &b.wi));
        }
        if (rd) *rd = d;
        return b;
    }

    void check(bool reflect_it) const {
        Point2f p{30.5f, 27.5f};
        RayDifferentials in;
        Bounce b = bounce(p, reflect_it, &in);
        RayDifferentials out = specular_differentials(b.hit, in, b.wi, reflect_it, b.etap);
        ASSERT_TRUE(out.valid);
        const float e = 0.02f;
        Bounce xp = bounce({p.x + e, p.y}, reflect_it), xm = bounce({p.x - e, p.y}, reflect_it);
        Bounce yp = bounce({p.x, p.y + e}, reflect_it), ym = bounce({p.x, p.y - e}, reflect_it);
        Vector3f dwdx = (xp.wi - xm.wi) / (2 * e) * kScale, dwdy = (yp.wi - ym.wi) / (2 * e) * kScale;
        Vector3f dpdx = (xp.hit.p - xm.hit.p) / (2 * e) * kScale,
                 dpdy = (yp.hit.p - ym.hit.p) / (2 * e) * kScale;
        // First-order agreement: the differentials span 1/8 pixel, whose second-order terms are a few
        // percent of the first-order ones here.
        expect_near(out.rx_direction - b.wi, dwdx, 0.03f * length(dwdx), "x direction");
        expect_near(out.ry_direction - b.wi, dwdy, 0.03f * length(dwdy), "y direction");
        expect_near(out.rx_origin - b.hit.p, dpdx, 0.03f * length(dpdx), "x origin");
        expect_near(out.ry_origin - b.hit.p, dpdy, 0.03f * length(dpdy), "y origin");
    }

    static constexpr float kScale = 0.125f;
    static constexpr float kEta = 1.5f;
    std::unique_ptr<Scene> scene_;
};

TEST_F(SpecularDifferentials, MirrorReflectionMatchesFiniteDifferences) { check(true); }
TEST_F(SpecularDifferentials, RefractionMatchesFiniteDifferences) { check(false); }

} // namespace
} // namespace illum
