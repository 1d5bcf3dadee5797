#include "illum/math/transform.h"

#include <cmath>
#include <stdexcept>

namespace illum {

Matrix4 Matrix4::identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
}

bool Matrix4::is_finite() const {
    for (auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) return false;
    return true;
}

Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Matrix4 transpose(const Matrix4& a) {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[j][i];
    return r;
}

std::optional<Matrix4> inverse(const Matrix4& a) {
    Matrix4 r = a;
    int indxc[4], indxr[4], ipiv[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4; i++) {
        int irow = 0, icol = 0;
        double big = 0;
        for (int j = 0; j < 4; j++) {
            if (ipiv[j] == 1) continue;
            for (int k = 0; k < 4; k++) {
                if (ipiv[k] == 0 && std::abs(r.m[j][k]) >= big) {
                    big = std::abs(r.m[j][k]);
                    irow = j;
                    icol = k;
                } else if (ipiv[k] > 1) {
                    return std::nullopt;
                }
            }
        }
        ++ipiv[icol];
        if (irow != icol) std::swap(r.m[irow], r.m[icol]);
        indxr[i] = irow;
        indxc[i] = icol;
        if (r.m[icol][icol] == 0 || !std::isfinite(r.m[icol][icol])) return std::nullopt;
        double pivinv = 1 / r.m[icol][icol];
        r.m[icol][icol] = 1;
        for (int j = 0; j < 4; j++) r.m[icol][j] *= pivinv;
        for (int j = 0; j < 4; j++) {
            if (j == icol) continue;
            double save = r.m[j][icol];
            r.m[j][icol] = 0;
            for (int k = 0; k < 4; k++) r.m[j][k] -= r.m[icol][k] * save;
        }
    }
    for (int j = 3; j >= 0; j--)
        if (indxr[j] != indxc[j])
            for (int k = 0; k < 4; k++) std::swap(r.m[k][indxr[j]], r.m[k][indxc[j]]);
    if (!r.is_finite()) return std::nullopt;
    return r;
}

Transform::Transform(const Matrix4& m) : m_(m) {
    auto inv = illum::inverse(m);
    if (!inv) throw std::invalid_argument("singular transform matrix");
    inv_ = *inv;
}

Transform Transform::translate(Vector3f d) {
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        m.m[i][3] = d[i];
        inv.m[i][3] = -d[i];
    }
    return {m, inv};
}

Transform Transform::scale(float x, float y, float z) {
    if (x == 0 || y == 0 || z == 0) throw std::invalid_argument("scale by zero");
    Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
    double s[3] = {x, y, z};
    for (int i = 0; i < 3; ++i) {
        m.m[i][i] = s[i];
        inv.m[i][i] = 1 / s[i];
    }
    return {m, inv};
}

Transform Transform::rotate(float theta_deg, Vector3f axis) {
    double len = std::sqrt(double(axis.x) * axis.x + double(axis.y) * axis.y + double(axis.z) * axis.z);
    if (!(len > 0)) throw std::invalid_argument("rotation about a zero axis");
    double a[3] = {axis.x / len, axis.y / len, axis.z / len};
    double th = theta_deg * kPiD / 180.0, s = std::sin(th), c = std::cos(th);
    // Rodrigues' rotation formula as a matrix.
    Matrix4 m = Matrix4::identity();
    m.m[0][0] = a[0] * a[0] + (1 - a[0] * a[0]) * c;
    m.m[0][1] = a[0] * a[1] * (1 - c) - a[2] * s;
    m.m[0][2] = a[0] * a[2] * (1 - c) + a[1] * s;
    m.m[1][0] = a[0] * a[1] * (1 - c) + a[2] * s;
    m.m[1][1] = a[1] * a[1] + (1 - a[1] * a[1]) * c;
    m.m[1][2] = a[1] * a[2] * (1 - c) - a[0] * s;
    m.m[2][0] = a[0] * a[2] * (1 - c) - a[1] * s;
    m.m[2][1] = a[1] * a[2] * (1 - c) + a[0] * s;
    m.m[2][2] = a[2] * a[2] + (1 - a[2] * a[2]) * c;
    return {m, transpose(m)};
}

Transform Transform::look_at(Point3f eye, Point3f target, Vector3f up) {
    Vector3f dir = target - eye;
    if (!(length(dir) > 0)) throw std::invalid_argument("LookAt: eye and target coincide");
    dir = normalize(dir);
    if (!(length(up) > 0)) throw std::invalid_argument("LookAt: zero up vector");
    Vector3f right = cross(normalize(up), dir);
    if (!(length(right) > 1e-6f)) throw std::invalid_argument("LookAt: up vector parallel to view direction");
    right = normalize(right);
    Vector3f new_up = cross(dir, right);
    Matrix4 world_from_camera = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        world_from_camera.m[i][0] = right[i];
        world_from_camera.m[i][1] = new_up[i];
        world_from_camera.m[i][2] = dir[i];
        world_from_camera.m[i][3] = Vector3f(eye)[i];
    }
    auto camera_from_world = illum::inverse(world_from_camera);
    return {*camera_from_world, world_from_camera};
}

bool Transform::swaps_handedness() const {
    const auto& a = m_.m;
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                 a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    return det < 0;
}

Point3f Transform::operator()(Point3f p) const {
    const auto& a = m_.m;
    double x = a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3];
    double y = a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3];
    double z = a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3];
    double w = a[3][0] * p.x + a[3][1] * p.y + a[3][2] * p.z + a[3][3];
    if (w == 1) return {float(x), float(y), float(z)};
    return {float(x / w), float(y / w), float(z / w)};
}

Vector3f Transform::operator()(Vector3f v) const {
    const auto& a = m_.m;
    return {float(a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z),
            float(a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z),
            float(a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z)};
}

Normal3f Transform::operator()(Normal3f n) const {
    const auto& a = inv_.m;
    return {float(a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z),
            float(a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z),
            float(a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z)};
}

} // namespace illum
