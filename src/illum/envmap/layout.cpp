#include "illum/envmap/layout.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "illum/util/error.h"

namespace illum {

namespace {

// Probe frame (Xp right, Yp up, Zp towards the camera) <-> map frame (+z up): Xp = x, Yp = z, Zp = -y.
Vector3f map_from_probe(Vector3f p) { return {p.x, -p.z, p.y}; }
Vector3f probe_from_map(Vector3f d) { return {d.x, d.z, -d.y}; }

// Clarberg's equal-area octahedral map, square [-1, 1]² -> sphere. With the L1 "radius" r = 1 - |1 -
// (|p| + |q|)| from the centre, the sphere's z = ±(1 - r²) and the azimuth within a quadrant is
// proportional to the position along the diamond's edge.
Vector3f octahedral_to_sphere(float p, float q) {
    float ap = std::abs(p), aq = std::abs(q);
    float signed_dist = 1 - (ap + aq);
    float r = 1 - std::abs(signed_dist);
    float phi = (r == 0 ? 1.0f : (aq - ap) / r + 1) * (kPi / 4);
    float z = std::copysign(1 - r * r, signed_dist);
    float s = r * safe_sqrt(2 - r * r);
    return {std::copysign(std::cos(phi), p) * s, std::copysign(std::sin(phi), q) * s, z};
}

Point2f sphere_to_octahedral(Vector3f d) {
    float ax = std::abs(d.x), ay = std::abs(d.y), az = std::min(std::abs(d.z), 1.0f);
    float r = std::sqrt(1 - az);
    // Azimuth within the quadrant, as a fraction of π/2.
    float a = std::max(ax, ay), b = std::min(ax, ay);
    float f = a == 0 ? 0.0f : std::atan(b / a) * (2 / kPi);
    if (ax < ay) f = 1 - f;
    float q = f * r, p = r - q; // on the edge |p| + |q| = r of the upper hemisphere's diamond
    if (d.z < 0) {
        // Lower hemisphere: fold over the diamond's edge |p| + |q| = 1.
        std::swap(p, q);
        p = 1 - p;
        q = 1 - q;
    }
    return {std::copysign(p, d.x), std::copysign(q, d.y)};
}

// Cubemap faces in the order +X, -X, +Y, -Y, +Z, -Z; (s, t) in [-1, 1]², t down the image.
Vector3f cube_face_direction(int face, float s, float t) {
    switch (face) {
    case 0:
        return {1, -t, -s};
    case 1:
        return {-1, -t, s};
    case 2:
        return {s, 1, t};
    case 3:
        return {s, -1, -t};
    case 4:
        return {s, -t, 1};
    default:
        return {-s, -t, -1};
    }
}

} // namespace

const char* to_string(EnvLayout l) {
    switch (l) {
    case EnvLayout::LatLong:
        return "latlong";
    case EnvLayout::Octahedral:
        return "octahedral";
    case EnvLayout::MirrorBall:
        return "mirrorball";
    case EnvLayout::Angular:
        return "angular";
    case EnvLayout::Cubemap:
        return "cubemap";
    }
    return "?";
}

std::optional<EnvLayout> env_layout_from_string(const std::string& s) {
    if (s == "latlong" || s == "equirect" || s == "equirectangular") return EnvLayout::LatLong;
    if (s == "octahedral") return EnvLayout::Octahedral;
    if (s == "mirrorball") return EnvLayout::MirrorBall;
    if (s == "angular") return EnvLayout::Angular;
    if (s == "cubemap") return EnvLayout::Cubemap;
    return std::nullopt;
}

int env_layout_aspect(EnvLayout l) {
    switch (l) {
    case EnvLayout::LatLong:
        return 2;
    case EnvLayout::Cubemap:
        return 6;
    default:
        return 1;
    }
}

void check_env_layout_size(EnvLayout l, int width, int height, const std::string& what) {
    int aspect = env_layout_aspect(l);
    if (width <= 0 || height <= 0 || width != aspect * height)
        throw Error(fmt::format("{}: a {} environment map must be {}:1 (width = {} x height), not {}x{}",
                                what, to_string(l), aspect, aspect, width, height));
}

std::optional<Vector3f> env_direction(EnvLayout l, Point2f uv) {
    switch (l) {
    case EnvLayout::LatLong: {
        float phi = uv.x * 2 * kPi, theta = uv.y * kPi;
        float st = std::sin(theta);
        return Vector3f{st * std::cos(phi), st * std::sin(phi), std::cos(theta)};
    }
    case EnvLayout::Octahedral:
        return octahedral_to_sphere(2 * uv.x - 1, 2 * uv.y - 1);
    case EnvLayout::MirrorBall: {
        float a = 2 * uv.x - 1, b = 1 - 2 * uv.y;
        float r2 = a * a + b * b;
        if (r2 > 1) return std::nullopt;
        float nz = std::sqrt(1 - r2);
        return normalize(map_from_probe({2 * nz * a, 2 * nz * b, 2 * nz * nz - 1}));
    }
    case EnvLayout::Angular: {
        float a = 2 * uv.x - 1, b = 1 - 2 * uv.y;
        float r = std::sqrt(a * a + b * b);
        if (r > 1) return std::nullopt;
        float theta = kPi * r;
        float k = r > 0 ? std::sin(theta) / r : 0.0f;
        return normalize(map_from_probe({a * k, b * k, std::cos(theta)}));
    }
    case EnvLayout::Cubemap: {
        float x = std::clamp(uv.x, 0.0f, 1.0f) * 6;
        int face = std::min(int(x), 5);
        float s = 2 * (x - face) - 1, t = 2 * uv.y - 1;
        return normalize(cube_face_direction(face, s, t));
    }
    }
    return std::nullopt;
}

Point2f env_uv(EnvLayout l, Vector3f d) {
    switch (l) {
    case EnvLayout::LatLong: {
        // θ by atan2, well conditioned near the poles (acos(z) is not, and the Jacobian sin θ is small
        // there).
        float theta = std::atan2(std::sqrt(d.x * d.x + d.y * d.y), d.z);
        return {spherical_phi(d) * (0.5f / kPi), std::clamp(theta * kInvPi, 0.0f, 1.0f)};
    }
    case EnvLayout::Octahedral: {
        Point2f p = sphere_to_octahedral(d);
        return {std::clamp(0.5f * (p.x + 1), 0.0f, 1.0f), std::clamp(0.5f * (p.y + 1), 0.0f, 1.0f)};
    }
    case EnvLayout::MirrorBall: {
        Vector3f p = probe_from_map(d);
        Vector3f h = p + Vector3f{0, 0, 1}; // the normal that reflects the view ray into p
        float len2 = length_squared(h);
        Vector3f n = len2 > 1e-12f ? h / std::sqrt(len2) : Vector3f{1, 0, 0};
        return {0.5f * (n.x + 1), 0.5f * (1 - n.y)};
    }
    case EnvLayout::Angular: {
        Vector3f p = probe_from_map(d);
        float rxy = std::sqrt(p.x * p.x + p.y * p.y);
        float r = safe_acos(p.z) * kInvPi;
        float a = rxy > 0 ? p.x / rxy * r : r, b = rxy > 0 ? p.y / rxy * r : 0.0f;
        return {0.5f * (a + 1), 0.5f * (1 - b)};
    }
    case EnvLayout::Cubemap: {
        float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
        int face;
        float sc, tc, ma;
        if (ax >= ay && ax >= az) {
            face = d.x > 0 ? 0 : 1;
            ma = ax;
            sc = d.x > 0 ? -d.z : d.z;
            tc = -d.y;
        } else if (ay >= az) {
            face = d.y > 0 ? 2 : 3;
            ma = ay;
            sc = d.x;
            tc = d.y > 0 ? d.z : -d.z;
        } else {
            face = d.z > 0 ? 4 : 5;
            ma = az;
            sc = d.z > 0 ? d.x : -d.x;
            tc = -d.y;
        }
        float s = std::clamp(sc / ma, -1.0f, 1.0f), t = std::clamp(tc / ma, -1.0f, 1.0f);
        return {(face + 0.5f * (s + 1)) / 6, 0.5f * (t + 1)};
    }
    }
    return {};
}

float env_jacobian(EnvLayout l, Point2f uv) {
    switch (l) {
    case EnvLayout::LatLong:
        return 2 * kPi * kPi * std::sin(uv.y * kPi);
    case EnvLayout::Octahedral:
        return 4 * kPi;
    case EnvLayout::MirrorBall: {
        float a = 2 * uv.x - 1, b = 1 - 2 * uv.y;
        return a * a + b * b <= 1 ? 16.0f : 0.0f;
    }
    case EnvLayout::Angular: {
        float a = 2 * uv.x - 1, b = 1 - 2 * uv.y;
        float r = std::sqrt(a * a + b * b);
        if (r > 1) return 0;
        float theta = kPi * r;
        return 4 * kPi * kPi * (theta > 1e-4f ? std::sin(theta) / theta : 1.0f);
    }
    case EnvLayout::Cubemap: {
        float x = std::clamp(uv.x, 0.0f, 1.0f) * 6;
        int face = std::min(int(x), 5);
        float s = 2 * (x - face) - 1, t = 2 * uv.y - 1;
        float q = 1 + s * s + t * t;
        return 24 / (q * std::sqrt(q));
    }
    }
    return 0;
}

} // namespace illum
