// Rays and robust ray origins. A hit point carries a conservative bound on its floating-point error;
// new rays start just outside that error box along the normal, so they neither re-hit the surface they
// leave nor pass through nearby geometry (Pharr, Jakob & Humphreys, PBR 4th ed., §6.8).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "illum/math/vector.h"

namespace illum {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// γ_n = n ε / (1 - n ε), the bound on the relative error of n floating-point operations (Higham 2002).
constexpr float gamma_bound(int n) {
    constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
    return (n * eps) / (1 - n * eps);
}

class Medium;

struct Ray {
    Point3f o;
    Vector3f d;
    float tmax = kInfinity;
    // The instant the ray samples (motion blur): drawn in the camera's shutter interval for a camera
    // sample; every ray of its path carries it. (Beside tmax, where it costs the struct no size.)
    float time = 0;
    const Medium* medium = nullptr; // the participating medium the ray travels in (none: vacuum)

    Point3f operator()(float t) const { return o + d * t; }
};
// Rays are copied on every bounce: the time must not make them bigger (measured: 48 bytes cost 0.7% more
// instructions on the Cornell box).
static_assert(sizeof(Ray) == 8 * sizeof(float) + sizeof(void*), "Ray grew");

// The adjacent floats, by stepping the bit pattern (PBR 4th ed. §6.8.2): the same values as std::nextafter
// towards ±infinity, without its library call (about 1% of a volumetric render's instructions).
inline float next_float_up(float v) {
    if (std::isinf(v) && v > 0) return v;
    if (v == 0) v = 0; // -0 steps up like +0
    std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    bits = v >= 0 ? bits + 1 : bits - 1;
    return std::bit_cast<float>(bits);
}
inline float next_float_down(float v) {
    if (std::isinf(v) && v < 0) return v;
    if (v == 0) v = -0.0f; // +0 steps down like -0
    std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
    bits = v > 0 ? bits - 1 : bits + 1;
    return std::bit_cast<float>(bits);
}

// Moves p off the surface with normal n, on the side of w, past its error bound p_error. Each coordinate
// is then rounded one ulp further along the (signed) normal, so the origin leaves the surface even where
// the bound is zero (a coordinate that is exact, such as z on the plane z = 0).
inline Point3f offset_ray_origin(Point3f p, Vector3f p_error, Normal3f n, Vector3f w) {
    float d = dot(abs(Vector3f(n)), p_error);
    Vector3f side = dot(w, n) < 0 ? -Vector3f(n) : Vector3f(n);
    Point3f po = p + side * d;
    for (int i = 0; i < 3; ++i) {
        if (side[i] > 0)
            po[i] = next_float_up(po[i]);
        else if (side[i] < 0)
            po[i] = next_float_down(po[i]);
    }
    return po;
}

// The rays spawned at surfaces are always inlined: a ray returned from a call through memory and then
// copied or read as wider pieces than its fields were stored stalls on store forwarding (util/in_place.h).

// A ray leaving a surface point in direction d.
[[gnu::always_inline]] inline Ray spawn_ray(Point3f p, Vector3f p_error, Normal3f n, Vector3f d) {
    return {offset_ray_origin(p, p_error, n, d), d, kInfinity};
}

// A shadow ray from a surface point to a target point (its own offset already applied); tmax stops
// just short of the target (d is unnormalised: t = 1 at the target).
[[gnu::always_inline]] inline Ray spawn_ray_to(Point3f p, Vector3f p_error, Normal3f n, Point3f target) {
    Point3f o = offset_ray_origin(p, p_error, n, target - p);
    return {o, target - o, 1 - 1e-4f};
}

[[gnu::always_inline]] inline Ray spawn_ray_to(Point3f p, Vector3f p_error, Normal3f n, Point3f q,
                                               Vector3f q_error, Normal3f nq) {
    Point3f pf = offset_ray_origin(p, p_error, n, q - p);
    Point3f pt = offset_ray_origin(q, q_error, nq, pf - q);
    return {pf, pt - pf, 1 - 1e-4f};
}

} // namespace illum
