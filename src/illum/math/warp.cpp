#include "illum/math/warp.h"

#include <algorithm>
#include <cmath>

#include "illum/math/fast_trig.h"

namespace illum {

Point2f sample_uniform_disk_concentric(Point2f u) {
    float ox = 2 * u.x - 1, oy = 2 * u.y - 1;
    if (ox == 0 && oy == 0) return {0, 0};
    // θ = (π/4)(oy/ox) on the wedges around ±x; around ±y θ = π/2 - (π/4)(ox/oy), whose cosine and sine
    // are the sine and cosine of (π/4)(ox/oy): one angle in [-π/4, π/4] either way.
    float s, c;
    if (std::abs(ox) > std::abs(oy)) {
        fast_sincos_quarter((kPi / 4) * (oy / ox), &s, &c);
        return {ox * c, ox * s};
    }
    fast_sincos_quarter((kPi / 4) * (ox / oy), &s, &c);
    return {oy * s, oy * c};
}

Point2f sample_uniform_disk_polar(Point2f u) {
    float r = std::sqrt(u.x), s, c;
    fast_sincos_2pi(u.y, &s, &c);
    return {r * c, r * s};
}

Vector3f sample_uniform_hemisphere(Point2f u) {
    float z = u.x, r = safe_sqrt(1 - z * z), s, c;
    fast_sincos_2pi(u.y, &s, &c);
    return {r * c, r * s, z};
}

Vector3f sample_cosine_hemisphere(Point2f u) {
    // Malley's method: the disk point lifted to the hemisphere, z = √(1 - r²). The concentric map's radius
    // is r = max(|2u.x - 1|, |2u.y - 1|), so z is computed beside the angle's chain instead of after it
    // (a BSDF sample's direction is what the next ray waits for).
    const float r = std::max(std::abs(2 * u.x - 1), std::abs(2 * u.y - 1));
    const float z = safe_sqrt(1 - r * r);
    Point2f d = sample_uniform_disk_concentric(u);
    return {d.x, d.y, z};
}

Vector3f sample_uniform_sphere(Point2f u) {
    float z = 1 - 2 * u.x, r = safe_sqrt(1 - z * z), s, c;
    fast_sincos_2pi(u.y, &s, &c);
    return {r * c, r * s, z};
}

Vector3f sample_uniform_cone(Point2f u, float cos_theta_max) {
    float cos_theta = (1 - u.x) + u.x * cos_theta_max;
    float sin_theta = safe_sqrt(1 - cos_theta * cos_theta), s, c;
    fast_sincos_2pi(u.y, &s, &c);
    return {sin_theta * c, sin_theta * s, cos_theta};
}

std::array<float, 3> sample_uniform_triangle(Point2f u) {
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2;
        b0 = u.x - b1;
    }
    return {b0, b1, 1 - b0 - b1};
}

float spherical_triangle_area(Vector3f a, Vector3f b, Vector3f c) {
    // tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a) for unit vectors a, b, c.
    double num = std::abs(double(dot(a, cross(b, c))));
    double den = 1.0 + double(dot(a, b)) + double(dot(b, c)) + double(dot(c, a));
    return float(std::abs(2 * std::atan2(num, den)));
}

namespace {

// Double-precision vectors for the spherical triangle: in float, Arvo's formula cancels badly for small
// triangles (a 1.6e-3 sr triangle had its pdf off by 1.5e-4 and samples off by several percent).
struct Vec3d {
    double x, y, z;
};
Vec3d to_d(Vector3f v) { return {v.x, v.y, v.z}; }
Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d cross(Vec3d a, Vec3d b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(Vec3d a) { return std::sqrt(dot(a, a)); }
// False (and v unchanged) when v is zero or not finite.
bool normalize_in_place(Vec3d& v) {
    double l = length(v);
    if (!(l > 0) || !std::isfinite(l)) return false;
    v = v * (1 / l);
    return true;
}
} // namespace

float spherical_triangle_pdf(const std::array<Point3f, 3>& v, Point3f p) {
    Vec3d a = to_d(v[0] - p), b = to_d(v[1] - p), c = to_d(v[2] - p);
    if (!normalize_in_place(a) || !normalize_in_place(b) || !normalize_in_place(c)) return 0;
    Vec3d n_ab = cross(a, b), n_ca = cross(c, a);
    if (!normalize_in_place(n_ab) || !normalize_in_place(n_ca)) return 0;
    double area = 2 * std::atan2(std::abs(dot(a, cross(b, c))), 1 + dot(a, b) + dot(b, c) + dot(c, a));
    if (!(area > 0) || !std::isfinite(float(1 / area))) return 0;
    return float(1 / area);
}

// Arvo's method: pick the sub-triangle area uniformly to find the point C' on arc AC, then pick a point
// uniformly in cos along arc BC'. Computed in double throughout.
std::array<float, 3> sample_spherical_triangle(const std::array<Point3f, 3>& v, Point3f p, Point2f u,
                                               float* pdf) {
    *pdf = 0;
    Vec3d a = to_d(v[0] - p), b = to_d(v[1] - p), c = to_d(v[2] - p);
    if (!normalize_in_place(a) || !normalize_in_place(b) || !normalize_in_place(c)) return {};

    // Normals of the great circles through each pair of vertices.
    Vec3d n_ab = cross(a, b), n_ca = cross(c, a);
    if (!normalize_in_place(n_ab) || !normalize_in_place(n_ca)) return {};

    // Interior angle α at A, between the planes through A, B and A, C: its cosine and sine straight from
    // the planes' normals (no inverse trigonometry).
    Vec3d n_ac = n_ca * -1.0;
    double cos_alpha = std::clamp(dot(n_ab, n_ac), -1.0, 1.0);
    double sin_alpha = dot(cross(n_ab, n_ac), a); // |n_ab × n_ac| with the sign of the orientation
    if (sin_alpha < 0) sin_alpha = -sin_alpha;

    // The area α + β + γ - π cancels for small triangles; Van Oosterom & Strackee's formula does not.
    double area = 2 * std::atan2(std::abs(dot(a, cross(b, c))), 1 + dot(a, b) + dot(b, c) + dot(c, a));
    if (!(area > 0) || !std::isfinite(float(1 / area))) return {};

    // Arvo's closed form for cos of the arc A C' (his s, t, u, v; cos c = A·B), with
    // s = sin(A' - α) and t = cos(A' - α) expanded by the angle-difference identities.
    double area_pct = area * double(u.x);
    double sin_ap = std::sin(area_pct), cos_ap = std::cos(area_pct);
    double s = sin_ap * cos_alpha - cos_ap * sin_alpha, t = cos_ap * cos_alpha + sin_ap * sin_alpha;
    double k1 = t - cos_alpha, k2 = s + sin_alpha * dot(a, b);
    double den = (k2 * s + k1 * t) * sin_alpha;
    double cos_bp = den != 0 ? std::clamp(((k2 * t - k1 * s) * cos_alpha - k2) / den, -1.0, 1.0) : 1.0;
    double sin_bp = std::sqrt(std::max(0.0, 1 - cos_bp * cos_bp));
    // C' on the arc from A to C.
    Vec3d ca_perp = c - a * dot(c, a);
    if (!normalize_in_place(ca_perp)) return {};
    Vec3d cp = a * cos_bp + ca_perp * sin_bp;

    // A direction between B and C' with cos uniformly distributed.
    double cos_theta = 1 - double(u.y) * (1 - dot(cp, b));
    double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    Vec3d cpb_perp = cp - b * dot(cp, b);
    Vec3d w = b;
    if (normalize_in_place(cpb_perp)) w = b * cos_theta + cpb_perp * sin_theta;

    // Intersect the ray (p, w) with the triangle's plane to get barycentrics (Möller-Trumbore).
    Vec3d e1 = to_d(v[1] - v[0]), e2 = to_d(v[2] - v[0]);
    Vec3d s1 = cross(w, e2);
    double divisor = dot(s1, e1);
    if (divisor == 0 || !std::isfinite(divisor)) return {};
    double inv = 1 / divisor;
    Vec3d sp = to_d(p - v[0]);
    double b1 = std::clamp(dot(sp, s1) * inv, 0.0, 1.0);
    double b2 = std::clamp(dot(w, cross(sp, e1)) * inv, 0.0, 1.0);
    if (b1 + b2 > 1) {
        double sum = b1 + b2;
        b1 /= sum;
        b2 /= sum;
    }
    *pdf = float(1 / area);
    return {float(std::max(0.0, 1 - b1 - b2)), float(b1), float(b2)};
}

} // namespace illum
