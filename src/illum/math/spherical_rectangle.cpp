#include "illum/math/spherical_rectangle.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

// The rectangle in its local frame as seen from o (Ureña et al. 2013, §3).
struct LocalRectangle {
    Vector3f x, y, z;
    float x0, x1, y0, y1, z0;
};

LocalRectangle local_rectangle(Point3f o, Point3f s, Vector3f ex, Vector3f ey) {
    LocalRectangle r;
    float ex_len = length(ex), ey_len = length(ey);
    r.x = ex / ex_len;
    r.y = ey / ey_len;
    r.z = cross(r.x, r.y);
    Vector3f d = s - o;
    r.z0 = dot(d, r.z);
    if (r.z0 > 0) { // look at the rectangle from below
        r.z = -r.z;
        r.z0 = -r.z0;
    }
    r.x0 = dot(d, r.x);
    r.y0 = dot(d, r.y);
    r.x1 = r.x0 + ex_len;
    r.y1 = r.y0 + ey_len;
    return r;
}

// The solid angle of [x0, x1] × [y0, y1] at height z0 < 0, with the quantities the sampler reuses: the
// angles between the planes through o and the edges, S = γ0 + γ1 + γ2 + γ3 - 2π.
struct RectangleAngles {
    float b0, b1, k, solid_angle;
};

RectangleAngles angles(float x0, float x1, float y0, float y1, float z0) {
    Vector3f v00{x0, y0, z0}, v01{x0, y1, z0}, v10{x1, y0, z0}, v11{x1, y1, z0};
    // The inward normals of the four planes through o and the rectangle's edges.
    Vector3f n0 = normalize(cross(v00, v10)), n1 = normalize(cross(v10, v11)),
             n2 = normalize(cross(v11, v01)), n3 = normalize(cross(v01, v00));
    float g0 = safe_acos(-dot(n0, n1)), g1 = safe_acos(-dot(n1, n2)), g2 = safe_acos(-dot(n2, n3)),
          g3 = safe_acos(-dot(n3, n0));
    RectangleAngles a;
    a.b0 = n0.z;
    a.b1 = n2.z;
    a.k = 2 * kPi - g2 - g3;
    a.solid_angle = std::max(0.0f, g0 + g1 - a.k);
    return a;
}

} // namespace

float spherical_rectangle_solid_angle(Point3f o, Point3f s, Vector3f ex, Vector3f ey) {
    LocalRectangle r = local_rectangle(o, s, ex, ey);
    if (!(r.z0 < 0)) return 0;
    return angles(r.x0, r.x1, r.y0, r.y1, r.z0).solid_angle;
}

std::optional<SphericalRectangleSample> sample_spherical_rectangle(Point3f o, Point3f s, Vector3f ex,
                                                                   Vector3f ey, Point2f u) {
    LocalRectangle r = local_rectangle(o, s, ex, ey);
    if (!(r.z0 < 0)) return std::nullopt;
    RectangleAngles a = angles(r.x0, r.x1, r.y0, r.y1, r.z0);
    if (!(a.solid_angle > 0)) return std::nullopt;
    // xu: the edge of the sub-rectangle of solid angle u0 S (Ureña et al., eqs. 8-10).
    float au = u.x * a.solid_angle + a.k;
    float fu = (std::cos(au) * a.b0 - a.b1) / std::sin(au);
    float cu = std::clamp(std::copysign(1.0f, fu) / std::sqrt(fu * fu + a.b0 * a.b0), -1.0f, 1.0f);
    float xu = -(cu * r.z0) / safe_sqrt(1 - cu * cu);
    if (!std::isfinite(xu)) xu = cu > 0 ? r.x1 : r.x0;
    xu = std::clamp(xu, r.x0, r.x1);
    // yv: uniform in h = y / √(d² + y²) along the chord at xu.
    float d = std::sqrt(xu * xu + r.z0 * r.z0);
    float h0 = r.y0 / std::sqrt(d * d + r.y0 * r.y0), h1 = r.y1 / std::sqrt(d * d + r.y1 * r.y1);
    float hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    float yv = hv2 < 1 - 1e-6f ? hv * d / std::sqrt(1 - hv2) : r.y1;
    yv = std::clamp(yv, r.y0, r.y1);
    return SphericalRectangleSample{o + r.x * xu + r.y * yv + r.z * r.z0, 1 / a.solid_angle};
}

Point2f invert_spherical_rectangle_sample(Point3f o, Point3f s, Vector3f ex, Vector3f ey, Point3f p) {
    LocalRectangle r = local_rectangle(o, s, ex, ey);
    if (!(r.z0 < 0)) return {0.5f, 0.5f};
    Vector3f d3 = p - o;
    float xu = std::clamp(dot(d3, r.x), r.x0, r.x1), yv = std::clamp(dot(d3, r.y), r.y0, r.y1);
    float total = angles(r.x0, r.x1, r.y0, r.y1, r.z0).solid_angle;
    // u0: the share of the solid angle left of xu (the sampler makes it linear in u0).
    float u0 = 0;
    if (total > 0 && xu > r.x0) u0 = angles(r.x0, xu, r.y0, r.y1, r.z0).solid_angle / total;
    float d = std::sqrt(xu * xu + r.z0 * r.z0);
    float h0 = r.y0 / std::sqrt(d * d + r.y0 * r.y0), h1 = r.y1 / std::sqrt(d * d + r.y1 * r.y1),
          hv = yv / std::sqrt(d * d + yv * yv);
    float u1 = h1 != h0 ? (hv - h0) / (h1 - h0) : 0.5f;
    return {std::clamp(u0, 0.0f, 1.0f), std::clamp(u1, 0.0f, 1.0f)};
}

} // namespace illum
