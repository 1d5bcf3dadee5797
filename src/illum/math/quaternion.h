// Unit quaternions in double for rotations that are interpolated (motion blur): w + x i + y j + z k acts
// on a column vector v as q v q*. Conversion from a rotation matrix by Shoemake's method and spherical
// linear interpolation (Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985).
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/math/matrix3.h"

namespace illum {

struct Quaternion {
    double w = 1, x = 0, y = 0, z = 0;

    Quaternion operator+(const Quaternion& o) const { return {w + o.w, x + o.x, y + o.y, z + o.z}; }
    Quaternion operator-(const Quaternion& o) const { return {w - o.w, x - o.x, y - o.y, z - o.z}; }
    Quaternion operator*(double s) const { return {w * s, x * s, y * s, z * s}; }
    Quaternion operator-() const { return {-w, -x, -y, -z}; }
};

inline double dot(const Quaternion& a, const Quaternion& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Quaternion normalize(const Quaternion& q) { return q * (1 / std::sqrt(dot(q, q))); }

// The quaternion of a rotation matrix (row-major, acting on column vectors, determinant +1). Shoemake's
// method: the largest of w², x², y², z² is taken from the trace or a diagonal element, the others from
// the off-diagonal sums and differences, so no division is by a small number.
inline Quaternion quaternion_from_rotation(const Matrix3d& m) {
    auto at = [&](int r, int c) { return m[std::size_t(3 * r + c)]; };
    double trace = at(0, 0) + at(1, 1) + at(2, 2);
    Quaternion q;
    if (trace > 0) {
        double s = std::sqrt(trace + 1) * 2; // 4 w
        q = {s / 4, (at(2, 1) - at(1, 2)) / s, (at(0, 2) - at(2, 0)) / s, (at(1, 0) - at(0, 1)) / s};
    } else if (at(0, 0) > at(1, 1) && at(0, 0) > at(2, 2)) {
        double s = std::sqrt(1 + at(0, 0) - at(1, 1) - at(2, 2)) * 2; // 4 x
        q = {(at(2, 1) - at(1, 2)) / s, s / 4, (at(0, 1) + at(1, 0)) / s, (at(0, 2) + at(2, 0)) / s};
    } else if (at(1, 1) > at(2, 2)) {
        double s = std::sqrt(1 + at(1, 1) - at(0, 0) - at(2, 2)) * 2; // 4 y
        q = {(at(0, 2) - at(2, 0)) / s, (at(0, 1) + at(1, 0)) / s, s / 4, (at(1, 2) + at(2, 1)) / s};
    } else {
        double s = std::sqrt(1 + at(2, 2) - at(0, 0) - at(1, 1)) * 2; // 4 z
        q = {(at(1, 0) - at(0, 1)) / s, (at(0, 2) + at(2, 0)) / s, (at(1, 2) + at(2, 1)) / s, s / 4};
    }
    return normalize(q);
}

// The rotation matrix of a unit quaternion (row-major, acting on column vectors).
inline Matrix3d rotation_matrix(const Quaternion& q) {
    double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z, xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z,
           wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {1 - 2 * (yy + zz), 2 * (xy - wz),     2 * (xz + wy), //
            2 * (xy + wz),     1 - 2 * (xx + zz), 2 * (yz - wx), //
            2 * (xz - wy),     2 * (yz + wx),     1 - 2 * (xx + yy)};
}

// Spherical linear interpolation along the great arc from a (t = 0) to b (t = 1), at constant angular
// speed: (sin((1-t)θ) a + sin(tθ) b) / sin θ, cos θ = a·b. The caller picks the sign of b (the shorter
// arc has a·b >= 0). Nearly equal quaternions are interpolated linearly and renormalised (sin θ -> 0).
inline Quaternion slerp(const Quaternion& a, const Quaternion& b, double t) {
    double c = std::clamp(dot(a, b), -1.0, 1.0);
    if (c > 0.9995) return normalize(a * (1 - t) + b * t);
    double theta = std::acos(c), s = std::sin(theta);
    return a * (std::sin((1 - t) * theta) / s) + b * (std::sin(t * theta) / s);
}

} // namespace illum
