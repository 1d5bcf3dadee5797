// 4x4 affine/projective transforms with their inverses. Matrices are row-major and act on column
// vectors: p' = M p.
#pragma once

#include <array>
#include <optional>

#include "illum/math/vector.h"

namespace illum {

struct Matrix4 {
    std::array<std::array<double, 4>, 4> m{};

    static Matrix4 identity();
    double operator()(int r, int c) const { return m[r][c]; }
    double& operator()(int r, int c) { return m[r][c]; }
    bool operator==(const Matrix4&) const = default;
    bool is_finite() const;
};

Matrix4 operator*(const Matrix4& a, const Matrix4& b);
Matrix4 transpose(const Matrix4& a);
// Gauss-Jordan elimination with full pivoting; nullopt for a singular matrix.
std::optional<Matrix4> inverse(const Matrix4& a);

class Transform {
public:
    Transform() : m_(Matrix4::identity()), inv_(Matrix4::identity()) {}
    Transform(const Matrix4& m, const Matrix4& inv) : m_(m), inv_(inv) {}
    // Throws std::invalid_argument when m is singular.
    explicit Transform(const Matrix4& m);

    static Transform translate(Vector3f d);
    static Transform scale(float x, float y, float z);
    // Rotation by theta degrees about axis (right-handed rotation of the axis' frame).
    static Transform rotate(float theta_deg, Vector3f axis);
    // World-from-camera's inverse: the camera-from-world transform that looks from eye at target
    // (pbrt's LookAt: camera +z towards the target, +y towards up).
    static Transform look_at(Point3f eye, Point3f target, Vector3f up);

    const Matrix4& matrix() const { return m_; }
    const Matrix4& inverse_matrix() const { return inv_; }
    Transform inverse() const { return {inv_, m_}; }
    bool is_identity() const { return m_ == Matrix4::identity(); }
    // True when the transform flips handedness (negative determinant of the upper 3x3).
    bool swaps_handedness() const;

    Point3f operator()(Point3f p) const;
    Vector3f operator()(Vector3f v) const;
    Normal3f operator()(Normal3f n) const; // by the inverse transpose

    Transform operator*(const Transform& o) const { return {m_ * o.m_, o.inv_ * inv_}; }
    bool operator==(const Transform&) const = default;

private:
    Matrix4 m_, inv_;
};

} // namespace illum
