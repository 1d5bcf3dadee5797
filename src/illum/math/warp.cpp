#include "illum/math/warp.h"

#include <cmath>

namespace illum {

Point2f sample_uniform_disk_concentric(Point2f u) {
    float ox = 2 * u.x - 1, oy = 2 * u.y - 1;
    if (ox == 0 && oy == 0) return {0, 0};
    float r, theta;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = (kPi / 4) * (oy / ox);
    } else {
        r = oy;
        theta = kPiOver2 - (kPi / 4) * (ox / oy);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

Point2f sample_uniform_disk_polar(Point2f u) {
    float r = std::sqrt(u.x), theta = 2 * kPi * u.y;
    return {r * std::cos(theta), r * std::sin(theta)};
}

Vector3f sample_uniform_hemisphere(Point2f u) {
    float z = u.x, r = safe_sqrt(1 - z * z), phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f sample_cosine_hemisphere(Point2f u) {
    Point2f d = sample_uniform_disk_concentric(u);
    float z = safe_sqrt(1 - d.x * d.x - d.y * d.y);
    return {d.x, d.y, z};
}

Vector3f sample_uniform_sphere(Point2f u) {
    float z = 1 - 2 * u.x, r = safe_sqrt(1 - z * z), phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f sample_uniform_cone(Point2f u, float cos_theta_max) {
    float cos_theta = (1 - u.x) + u.x * cos_theta_max;
    float sin_theta = safe_sqrt(1 - cos_theta * cos_theta), phi = u.y * 2 * kPi;
    return spherical_direction(sin_theta, cos_theta, phi);
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

// Arvo's method: pick the sub-triangle area uniformly to find the point C' on arc AC, then pick a point
// uniformly in cos along arc BC'.
std::array<float, 3> sample_spherical_triangle(const std::array<Point3f, 3>& v, Point3f p, Point2f u,
                                               float* pdf) {
    *pdf = 0;
    Vector3f a = v[0] - p, b = v[1] - p, c = v[2] - p;
    if (length_squared(a) == 0 || length_squared(b) == 0 || length_squared(c) == 0) return {};
    a = normalize(a);
    b = normalize(b);
    c = normalize(c);

    // Normals of the great circles through each pair of vertices.
    Vector3f n_ab = cross(a, b), n_bc = cross(b, c), n_ca = cross(c, a);
    if (length_squared(n_ab) == 0 || length_squared(n_bc) == 0 || length_squared(n_ca) == 0) return {};
    n_ab = normalize(n_ab);
    n_bc = normalize(n_bc);
    n_ca = normalize(n_ca);

    // Interior angles at the vertices.
    auto angle_between = [](Vector3f x, Vector3f y) {
        return dot(x, y) < 0 ? kPi - 2 * safe_asin(length(x + y) / 2) : 2 * safe_asin(length(y - x) / 2);
    };
    float alpha = angle_between(n_ab, -n_ca);
    float beta = angle_between(n_bc, -n_ab);
    float gamma = angle_between(n_ca, -n_bc);

    float area = alpha + beta + gamma - kPi;
    if (!(area > 0)) return {};
    *pdf = 1 / area;

    // Area of the sub-triangle that the sample picks.
    float area_pct = area * u.x;
    float sin_phi = std::sin(area_pct - alpha), cos_phi = std::cos(area_pct - alpha);
    float cos_alpha = std::cos(alpha), sin_alpha = std::sin(alpha);
    float k1 = cos_phi + cos_alpha, k2 = sin_phi - sin_alpha * dot(a, b);
    float cos_bp = (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha) / ((k2 * sin_phi + k1 * cos_phi) * sin_alpha);
    cos_bp = std::clamp(cos_bp, -1.0f, 1.0f);
    float sin_bp = safe_sqrt(1 - cos_bp * cos_bp);
    // C' on the arc from A to C.
    Vector3f ca_perp = c - a * dot(c, a);
    if (length_squared(ca_perp) == 0) return {};
    Vector3f cp = a * cos_bp + normalize(ca_perp) * sin_bp;

    // A direction between B and C' with cos uniformly distributed.
    float cos_theta = 1 - u.y * (1 - dot(cp, b));
    float sin_theta = safe_sqrt(1 - cos_theta * cos_theta);
    Vector3f cpb_perp = cp - b * dot(cp, b);
    if (length_squared(cpb_perp) == 0) return {};
    Vector3f w = b * cos_theta + normalize(cpb_perp) * sin_theta;

    // Intersect the ray (p, w) with the triangle's plane to get barycentrics (Möller-Trumbore, in double).
    Vector3f e1 = v[1] - v[0], e2 = v[2] - v[0];
    Vector3f s1 = cross(w, e2);
    double divisor = dot(s1, e1);
    if (divisor == 0) {
        *pdf = 0;
        return {};
    }
    double inv = 1 / divisor;
    Vector3f s = p - v[0];
    double b1 = dot(s, s1) * inv;
    double b2 = dot(w, cross(s, e1)) * inv;
    b1 = std::clamp(b1, 0.0, 1.0);
    b2 = std::clamp(b2, 0.0, 1.0);
    if (b1 + b2 > 1) {
        double sum = b1 + b2;
        b1 /= sum;
        b2 /= sum;
    }
    return {float(1 - b1 - b2), float(b1), float(b2)};
}

} // namespace illum
