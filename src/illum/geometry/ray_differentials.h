// Ray differentials (Igehy 1999, "Tracing ray differentials"; PBR 4th ed. §10.1): two offset rays that
// follow a camera ray one pixel step away in x and in y. At a hit they give the footprint ∂p/∂x, ∂p/∂y and
// from it ∂u/∂x, ∂u/∂y, ∂v/∂x, ∂v/∂y, over which textures filter; through perfectly specular reflection
// and refraction they are carried along. They live beside the ray (Ray itself stays small) and are made
// only for scenes with filtered textures.
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/geometry/surface_hit.h"

namespace illum {

struct RayDifferentials {
    Point3f rx_origin, ry_origin;
    Vector3f rx_direction, ry_direction;
    bool valid = false;

    // pbrt-v4's RayDifferential::ScaleDifferentials: the offsets scaled by s about the main ray, so that
    // they span the spacing of s·(one pixel) (the camera uses s = max(1/8, 1/sqrt(spp))).
    void scale(const Ray& ray, float s) {
        rx_origin = ray.o + (rx_origin - ray.o) * s;
        ry_origin = ray.o + (ry_origin - ray.o) * s;
        rx_direction = ray.d + (rx_direction - ray.d) * s;
        ry_direction = ray.d + (ry_direction - ray.d) * s;
    }
    // The offset rays' origins moved by t along their directions (pbrt-v4's SkipIntersection: a path that
    // passes a surface without scattering).
    void advance(float t) {
        rx_origin = rx_origin + rx_direction * t;
        ry_origin = ry_origin + ry_direction * t;
    }
};

// The footprint from the offset rays: where each meets the hit's tangent plane n·x = n·p, minus p
// (PBR 4th ed. §10.1.1). false when an offset ray is parallel to the plane.
inline bool footprint_from_differentials(const SurfaceHit& hit, const RayDifferentials& rd, Vector3f* dpdx,
                                         Vector3f* dpdy) {
    Vector3f n(hit.n);
    float ndx = dot(n, rd.rx_direction), ndy = dot(n, rd.ry_direction);
    if (ndx == 0 || ndy == 0) return false;
    float d = dot(n, Vector3f(hit.p));
    float tx = (d - dot(n, Vector3f(rd.rx_origin))) / ndx;
    float ty = (d - dot(n, Vector3f(rd.ry_origin))) / ndy;
    *dpdx = (rd.rx_origin + rd.rx_direction * tx) - hit.p;
    *dpdy = (rd.ry_origin + rd.ry_direction * ty) - hit.p;
    return is_finite(*dpdx) && is_finite(*dpdy);
}

// ∂u/∂x, ∂v/∂x (and in y) as the least-squares solution of ∂p/∂x = ∂u/∂x ∂p/∂u + ∂v/∂x ∂p/∂v (the normal
// equations AᵀA [∂u/∂x ∂v/∂x]ᵀ = Aᵀ ∂p/∂x, A = [∂p/∂u ∂p/∂v]; PBR 4th ed. §10.1.1). Each is clamped to
// ±10^8 and set to 0 where not finite (a degenerate parameterisation), as pbrt-v4 does.
inline void set_uv_derivatives(TextureEvalContext& c, Vector3f dpdx, Vector3f dpdy, Vector3f dpdu,
                               Vector3f dpdv) {
    c.dpdx = dpdx;
    c.dpdy = dpdy;
    double a00 = dot(dpdu, dpdu), a01 = dot(dpdu, dpdv), a11 = dot(dpdv, dpdv);
    double det = a00 * a11 - a01 * a01;
    double inv = det != 0 ? 1 / det : 0;
    if (!std::isfinite(inv)) inv = 0;
    double bx0 = dot(dpdu, dpdx), bx1 = dot(dpdv, dpdx), by0 = dot(dpdu, dpdy), by1 = dot(dpdv, dpdy);
    auto tame = [](double v) { return std::isfinite(v) ? float(std::clamp(v, -1e8, 1e8)) : 0.0f; };
    c.dudx = tame((a11 * bx0 - a01 * bx1) * inv);
    c.dvdx = tame((a00 * bx1 - a01 * bx0) * inv);
    c.dudy = tame((a11 * by0 - a01 * by1) * inv);
    c.dvdy = tame((a00 * by1 - a01 * by0) * inv);
}

// The differentials of the ray leaving a hit along wi by perfect specular reflection (reflection = true)
// or refraction with relative index eta (BSDFSample::eta), from those of the ray that arrived
// (PBR 4th ed. §10.1.3, Igehy 1999). The hit's footprint (dpdx, dudx, ...) and its shading partials (∂n/∂u,
// ∂n/∂v) must be set. With ∂n/∂x = ∂n/∂u ∂u/∂x + ∂n/∂v ∂v/∂x and ∂ωo/∂x the change of the incoming
// direction:
//   reflection  ωi = -ωo + 2 (ωo·n) n:  ∂ωi/∂x = -∂ωo/∂x + 2 ((ωo·n) ∂n/∂x + ∂(ωo·n)/∂x n);
//   refraction  ωi = -ωo/η + μ n, μ = (ωo·n)/η - |ωi·n| (n on ωo's side):
//     ∂ωi/∂x = -∂ωo/∂x / η + μ ∂n/∂x + ∂μ/∂x n, ∂μ/∂x = ∂(ωo·n)/∂x (1/η + (ωo·n) / (η² (ωi·n))).
// (pbrt-v4 (5f7a606) writes -η ∂ωo/∂x in the refracted direction, which is the derivative only for η = 1;
// illum uses -∂ωo/∂x / η, checked against finite differences in tests/geometry.) The offset rays start at
// p + ∂p/∂x and p + ∂p/∂y. Invalid (none carried) when the result is huge, as pbrt-v4 squashes it.
inline RayDifferentials specular_differentials(const SurfaceHit& hit, const RayDifferentials& in, Vector3f wi,
                                               bool reflection, float eta) {
    RayDifferentials rd;
    if (!in.valid) return rd;
    Vector3f wo = hit.wo, n(hit.ns);
    Vector3f dndx = Vector3f(hit.dndu) * hit.dudx + Vector3f(hit.dndv) * hit.dvdx;
    Vector3f dndy = Vector3f(hit.dndu) * hit.dudy + Vector3f(hit.dndv) * hit.dvdy;
    Vector3f dwodx = -in.rx_direction - wo, dwody = -in.ry_direction - wo;
    rd.rx_origin = hit.p + hit.dpdx;
    rd.ry_origin = hit.p + hit.dpdy;
    if (reflection) {
        float dwon_dx = dot(dwodx, n) + dot(wo, dndx), dwon_dy = dot(dwody, n) + dot(wo, dndy);
        float won = dot(wo, n);
        rd.rx_direction = wi - dwodx + (dndx * won + n * dwon_dx) * 2;
        rd.ry_direction = wi - dwody + (dndy * won + n * dwon_dy) * 2;
    } else {
        if (dot(wo, n) < 0) {
            n = -n;
            dndx = -dndx;
            dndy = -dndy;
        }
        float won = dot(wo, n), win = dot(wi, n);
        float dwon_dx = dot(dwodx, n) + dot(wo, dndx), dwon_dy = dot(dwody, n) + dot(wo, dndy);
        float mu = won / eta - std::abs(win);
        float k = 1 / eta + won / (eta * eta * win);
        rd.rx_direction = wi - dwodx / eta + dndx * mu + n * (dwon_dx * k);
        rd.ry_direction = wi - dwody / eta + dndy * mu + n * (dwon_dy * k);
    }
    auto huge = [](Vector3f v) { return !(length_squared(v) <= 1e16f); };
    rd.valid = !(huge(rd.rx_direction) || huge(rd.ry_direction) || huge(Vector3f(rd.rx_origin)) ||
                 huge(Vector3f(rd.ry_origin)));
    return rd;
}

} // namespace illum
