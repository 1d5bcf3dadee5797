#include "illum/light/light_bounds.h"

#include <algorithm>
#include <cmath>

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
