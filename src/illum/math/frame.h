// Orthonormal frames: the shading frame puts the normal on +z (DESIGN.md §3).
#pragma once

#include "illum/math/vector.h"

namespace illum {

// Branchless orthonormal basis from a unit vector (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited", JCGT 6(1)).
inline void coordinate_system(Vector3f n, Vector3f* s, Vector3f* t) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    *s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
    *t = {b, sign + n.y * n.y * a, -n.y};
}

struct Frame {
    Vector3f s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

    Frame() = default;
    Frame(Vector3f s_, Vector3f t_, Vector3f n_) : s(s_), t(t_), n(n_) {}
    static Frame from_z(Vector3f z) {
        Frame f;
        f.n = z;
        coordinate_system(z, &f.s, &f.t);
        return f;
    }
    static Frame from_z(Normal3f z) { return from_z(Vector3f(z)); }
    // A frame with normal z whose s axis follows the tangent x as closely as orthogonality allows.
    // Always inlined: a frame returned from a call is copied out of its return slot right after the call's
    // stores, a store-forwarding stall (util/in_place.h) that cost more than the frame's arithmetic.
    [[gnu::always_inline]] static Frame from_xz(Vector3f x, Vector3f z) {
        Vector3f s = x - z * dot(x, z);
        float len2 = length_squared(s);
        if (!(len2 > 1e-12f)) return from_z(z);
        s = s / std::sqrt(len2);
        return {s, cross(z, s), z};
    }
    Vector3f to_local(Vector3f v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vector3f to_world(Vector3f v) const { return s * v.x + t * v.y + n * v.z; }
};

// Trigonometry of a direction in the local shading frame.
inline float cos_theta(Vector3f w) { return w.z; }
inline float abs_cos_theta(Vector3f w) { return std::abs(w.z); }
inline float cos2_theta(Vector3f w) { return w.z * w.z; }
inline float sin2_theta(Vector3f w) { return std::max(0.0f, 1.0f - cos2_theta(w)); }
inline float sin_theta(Vector3f w) { return std::sqrt(sin2_theta(w)); }
inline float tan2_theta(Vector3f w) { return sin2_theta(w) / cos2_theta(w); }
inline float cos_phi(Vector3f w) {
    float st = sin_theta(w);
    return st == 0 ? 1.0f : std::clamp(w.x / st, -1.0f, 1.0f);
}
inline float sin_phi(Vector3f w) {
    float st = sin_theta(w);
    return st == 0 ? 0.0f : std::clamp(w.y / st, -1.0f, 1.0f);
}
inline bool same_hemisphere(Vector3f a, Vector3f b) { return a.z * b.z > 0; }
inline Vector3f reflect(Vector3f wo, Vector3f n) { return -wo + n * (2 * dot(wo, n)); }

} // namespace illum
