#include "illum/math/direction_cone.h"

#include "illum/math/frame.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {
// v turned by the angle theta about the unit axis k (Rodrigues' formula).
Vector3f rotate(Vector3f v, Vector3f k, float theta) {
    float c = std::cos(theta), s = std::sin(theta);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}
} // namespace

DirectionCone union_of(const DirectionCone& a, const DirectionCone& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    float theta_a = safe_acos(a.cos_theta), theta_b = safe_acos(b.cos_theta);
    float theta_d = safe_acos(dot(a.w, b.w));
    if (std::min(theta_d + theta_b, kPi) <= theta_a) return a;
    if (std::min(theta_d + theta_a, kPi) <= theta_b) return b;
    float theta_o = (theta_a + theta_d + theta_b) / 2;
    if (theta_o >= kPi) return DirectionCone::entire_sphere();
    Vector3f k = cross(a.w, b.w);
    float k2 = length_squared(k);
    if (k2 < 1e-12f) {
        // Parallel axes: the wider cone (up to rounding). Opposite ones: any plane through the axes will
        // do to turn in.
        if (dot(a.w, b.w) > 0) return theta_a >= theta_b ? a : b;
        Vector3f t;
        coordinate_system(a.w, &k, &t);
        k2 = 1;
    }
    Vector3f w = rotate(a.w, k / std::sqrt(k2), theta_o - theta_a);
    return DirectionCone(w, std::cos(theta_o));
}

DirectionCone directions_towards(const Bounds3f& b, Point3f p) {
    Point3f c;
    float r = 0;
    b.bounding_sphere(&c, &r);
    float d2 = distance_squared(p, c);
    if (d2 <= r * r) return DirectionCone::entire_sphere();
    float sin2 = r * r / d2;
    return DirectionCone(c - p, safe_sqrt(1 - sin2));
}

} // namespace illum
