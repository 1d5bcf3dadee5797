#include "illum/light/light_bounds.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace illum {

namespace {
// cos(max(0, a - b)) from the cosines and sines of a and b: 1 when a ≤ b, else cos a cos b + sin a sin b.
float cos_minus_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a >= cos_b) return 1;
    return cos_a * cos_b + sin_a * sin_b;
}
// sin(max(0, a - b)): 0 when a ≤ b, else sin a cos b - cos a sin b.
float sin_minus_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
    if (cos_a >= cos_b) return 0;
    return sin_a * cos_b - cos_a * sin_b;
}
} // namespace

PreparedLightBounds::PreparedLightBounds(const LightBounds& b)
    : centre(b.bounds.center()), r2(length_squared(b.bounds.diagonal()) / 4), w(b.w), phi(b.phi),
      cos_theta_o(b.cos_theta_o), sin_theta_o(safe_sqrt(1 - b.cos_theta_o * b.cos_theta_o)),
      cos_theta_e(b.cos_theta_e), two_sided(b.two_sided) {}

float LightBounds::importance(Point3f p, Normal3f n) const {
    return PreparedLightBounds(*this).importance(p, n);
}

float PreparedLightBounds::importance(Point3f p, Normal3f n) const {
    // The box's bounding sphere: centre, radius² r2 (directions_towards' cone, written out).
    Vector3f v = p - centre;
    float dist2 = length_squared(v);
    // d no less than a quarter of the bounding radius: enough to keep a receiver near a small group's
    // centre from taking every sample, small enough that receivers inside a large node still tell its
    // near half from its far one. (Clamping at the radius itself, as first written, doubled the RMSE of
    // scripts/many_lights.py at equal samples; pbrt-v4 clamps d² at half the diagonal's length, which
    // measured the same as r / 4 there but depends on the scene's scale.)
    float d2 = std::max(dist2, r2 / 16);
    if (d2 <= 0) return 0; // a point emitter at the receiver itself: it reaches no direction there

    // θw: from the normal axis to the direction from the centre towards p (either side when two-sided).
    // (p at the centre of a box: θb below is π, and the direction does not matter.)
    Vector3f to_p = dist2 > 0 ? v * (1 / std::sqrt(dist2)) : Vector3f{};
    float cos_w = dot(w, to_p);
    if (two_sided) cos_w = std::abs(cos_w);
    float sin_w = safe_sqrt(1 - cos_w * cos_w);

    // θb: the half-angle the box's bounding sphere subtends from p, sin θb = r / dist (π from inside).
    float sin_b = 0, cos_b = -1;
    if (dist2 > r2) {
        float sin2_b = r2 / dist2;
        sin_b = std::sqrt(sin2_b);
        cos_b = std::sqrt(1 - sin2_b);
    }

    // θ' = max(0, θw - θo - θb), in two clamped steps.
    float cos_x = cos_minus_clamped(sin_w, cos_w, sin_theta_o, cos_theta_o);
    float sin_x = sin_minus_clamped(sin_w, cos_w, sin_theta_o, cos_theta_o);
    float cos_p = cos_minus_clamped(sin_x, cos_x, sin_b, cos_b);
    if (cos_p <= cos_theta_e) return 0;

    float importance = phi * cos_p / d2;
    if (n != Normal3f{}) {
        float cos_i = abs_dot(n, to_p); // n is a unit normal
        float sin_i = safe_sqrt(1 - cos_i * cos_i);
        importance *= cos_minus_clamped(sin_i, cos_i, sin_b, cos_b);
    }
    return std::max(importance, 0.0f);
}

#if defined(__SSE2__)
namespace {
// Lane 0 holds a's value, lanes 1-3 b's (lanes 2 and 3 are computed and not read).
__m128 lanes(float a, float b) { return _mm_setr_ps(a, b, b, b); }
// mask ? t : f, lane by lane.
__m128 select(__m128 mask, __m128 t, __m128 f) {
    return _mm_or_ps(_mm_and_ps(mask, t), _mm_andnot_ps(mask, f));
}
__m128 abs_lanes(__m128 x) { return _mm_and_ps(x, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff))); }
// safe_sqrt: sqrt(std::max(0, x)), that is x where 0 < x, else 0 (NaN too).
__m128 safe_sqrt_lanes(__m128 x) {
    return _mm_sqrt_ps(select(_mm_cmplt_ps(_mm_setzero_ps(), x), x, _mm_setzero_ps()));
}
__m128 cos_minus_clamped_lanes(__m128 sin_a, __m128 cos_a, __m128 sin_b, __m128 cos_b) {
    __m128 v = _mm_add_ps(_mm_mul_ps(cos_a, cos_b), _mm_mul_ps(sin_a, sin_b));
    return select(_mm_cmpge_ps(cos_a, cos_b), _mm_set1_ps(1), v);
}
__m128 sin_minus_clamped_lanes(__m128 sin_a, __m128 cos_a, __m128 sin_b, __m128 cos_b) {
    __m128 v = _mm_sub_ps(_mm_mul_ps(sin_a, cos_b), _mm_mul_ps(cos_a, sin_b));
    return select(_mm_cmpge_ps(cos_a, cos_b), _mm_setzero_ps(), v);
}
// a.x b.x + a.y b.y + a.z b.z, summed left to right as dot() does.
__m128 dot_lanes(__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}
} // namespace

void importance_pair(const PreparedLightBounds& a, const PreparedLightBounds& b, Point3f p, Normal3f n,
                     float* importance_a, float* importance_b) {
    // importance() above, step by step; a lane's early returns become masks applied at the end.
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1);
    __m128 vx = _mm_sub_ps(_mm_set1_ps(p.x), lanes(a.centre.x, b.centre.x));
    __m128 vy = _mm_sub_ps(_mm_set1_ps(p.y), lanes(a.centre.y, b.centre.y));
    __m128 vz = _mm_sub_ps(_mm_set1_ps(p.z), lanes(a.centre.z, b.centre.z));
    __m128 dist2 = dot_lanes(vx, vy, vz, vx, vy, vz);
    __m128 r2 = lanes(a.r2, b.r2);
    __m128 r2_16 = _mm_div_ps(r2, _mm_set1_ps(16));
    __m128 d2 = select(_mm_cmplt_ps(dist2, r2_16), r2_16, dist2); // std::max(dist2, r2 / 16)
    __m128 dead = _mm_cmple_ps(d2, zero);

    __m128 positive = _mm_cmpgt_ps(dist2, zero);
    __m128 inv = _mm_div_ps(one, _mm_sqrt_ps(dist2));
    __m128 tx = select(positive, _mm_mul_ps(vx, inv), zero), ty = select(positive, _mm_mul_ps(vy, inv), zero),
           tz = select(positive, _mm_mul_ps(vz, inv), zero);
    __m128 cos_w = dot_lanes(lanes(a.w.x, b.w.x), lanes(a.w.y, b.w.y), lanes(a.w.z, b.w.z), tx, ty, tz);
    __m128 two_sided = _mm_castsi128_ps(_mm_setr_epi32(a.two_sided ? -1 : 0, b.two_sided ? -1 : 0,
                                                       b.two_sided ? -1 : 0, b.two_sided ? -1 : 0));
    cos_w = select(two_sided, abs_lanes(cos_w), cos_w);
    __m128 sin_w = safe_sqrt_lanes(_mm_sub_ps(one, _mm_mul_ps(cos_w, cos_w)));

    __m128 outside = _mm_cmpgt_ps(dist2, r2);
    __m128 sin2_b = _mm_div_ps(r2, dist2);
    __m128 sin_b = select(outside, _mm_sqrt_ps(sin2_b), zero);
    __m128 cos_b = select(outside, _mm_sqrt_ps(_mm_sub_ps(one, sin2_b)), _mm_set1_ps(-1));

    __m128 sin_o = lanes(a.sin_theta_o, b.sin_theta_o), cos_o = lanes(a.cos_theta_o, b.cos_theta_o);
    __m128 cos_x = cos_minus_clamped_lanes(sin_w, cos_w, sin_o, cos_o);
    __m128 sin_x = sin_minus_clamped_lanes(sin_w, cos_w, sin_o, cos_o);
    __m128 cos_p = cos_minus_clamped_lanes(sin_x, cos_x, sin_b, cos_b);
    dead = _mm_or_ps(dead, _mm_cmple_ps(cos_p, lanes(a.cos_theta_e, b.cos_theta_e)));

    __m128 importance = _mm_div_ps(_mm_mul_ps(lanes(a.phi, b.phi), cos_p), d2);
    if (n != Normal3f{}) {
        __m128 cos_i = abs_lanes(dot_lanes(_mm_set1_ps(n.x), _mm_set1_ps(n.y), _mm_set1_ps(n.z), tx, ty, tz));
        __m128 sin_i = safe_sqrt_lanes(_mm_sub_ps(one, _mm_mul_ps(cos_i, cos_i)));
        importance = _mm_mul_ps(importance, cos_minus_clamped_lanes(sin_i, cos_i, sin_b, cos_b));
    }
    importance = select(_mm_cmplt_ps(importance, zero), zero, importance); // std::max(importance, 0)
    importance = select(dead, zero, importance);
    alignas(16) float out[4];
    _mm_store_ps(out, importance);
    *importance_a = out[0];
    *importance_b = out[1];
}
#else
void importance_pair(const PreparedLightBounds& a, const PreparedLightBounds& b, Point3f p, Normal3f n,
                     float* importance_a, float* importance_b) {
    *importance_a = a.importance(p, n);
    *importance_b = b.importance(p, n);
}
#endif

LightBounds point_bounds(Point3f p, float phi) {
    LightBounds b;
    b.bounds.extend(p);
    b.phi = phi;
    b.cos_theta_o = -1;
    b.cos_theta_e = 0;
    return b;
}

LightBounds union_of(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0) return b;
    if (b.phi == 0) return a;
    DirectionCone cone = union_of(DirectionCone(a.w, a.cos_theta_o), DirectionCone(b.w, b.cos_theta_o));
    LightBounds u;
    u.bounds = a.bounds;
    u.bounds.extend(b.bounds);
    u.w = cone.w;
    u.phi = a.phi + b.phi;
    u.cos_theta_o = cone.cos_theta;
    u.cos_theta_e = std::min(a.cos_theta_e, b.cos_theta_e);
    u.two_sided = a.two_sided || b.two_sided;
    return u;
}

} // namespace illum
