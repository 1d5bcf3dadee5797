#include "illum/math/animated_transform.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

Matrix3d transpose3(const Matrix3d& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

double det3(const Matrix3d& a) {
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
}

} // namespace

bool is_affine(const Matrix4& m) { return m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1; }

Matrix4 TransformComponents::matrix() const {
    Matrix3d rs = multiply(rotation_matrix(rotation), scale);
    Matrix4 m = Matrix4::identity();
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m(r, c) = rs[std::size_t(3 * r + c)];
        m(r, 3) = translation[std::size_t(r)];
    }
    return m;
}

TransformComponents decompose(const Matrix4& m) {
    TransformComponents c;
    Matrix3d a;
    for (int r = 0; r < 3; ++r) {
        c.translation[std::size_t(r)] = m(r, 3);
        for (int k = 0; k < 3; ++k) a[std::size_t(3 * r + k)] = m(r, k);
    }
    // Polar decomposition: the average of R and its inverse transpose converges (quadratically) to the
    // orthogonal factor.
    Matrix3d rot = a;
    for (int it = 0; it < 100; ++it) {
        auto inv = inverse(rot);
        if (!inv) break;
        Matrix3d inv_t = transpose3(*inv), next;
        double change = 0;
        for (std::size_t i = 0; i < 9; ++i) {
            next[i] = 0.5 * (rot[i] + inv_t[i]);
            change = std::max(change, std::abs(next[i] - rot[i]));
        }
        rot = next;
        if (change < 1e-14) break;
    }
    Matrix3d s = multiply(transpose3(rot), a);
    if (det3(rot) < 0)
        for (std::size_t i = 0; i < 9; ++i) {
            rot[i] = -rot[i];
            s[i] = -s[i];
        }
    c.rotation = quaternion_from_rotation(rot);
    c.scale = s;
    return c;
}

AnimatedTransform::AnimatedTransform(const Transform& start, double start_time, const Transform& end,
                                     double end_time)
    : start_(start), end_(end), t0_(start_time), t1_(end_time) {
    animated_ = !(start == end);
    if (!animated_) return;
    c0_ = decompose(start.matrix());
    c1_ = decompose(end.matrix());
    // The shorter arc: q and -q are the same rotation.
    if (dot(c0_.rotation, c1_.rotation) < 0) c1_.rotation = -c1_.rotation;
}

TransformComponents AnimatedTransform::components(double time) const {
    if (!animated_) return decompose(start_.matrix());
    // Equal times (pbrt-v4 allows them) make a step: the start up to that time, the end after it.
    double u = t1_ > t0_ ? std::clamp((time - t0_) / (t1_ - t0_), 0.0, 1.0) : time <= t0_ ? 0.0 : 1.0;
    TransformComponents c;
    for (std::size_t i = 0; i < 3; ++i)
        c.translation[i] = (1 - u) * c0_.translation[i] + u * c1_.translation[i];
    c.rotation = slerp(c0_.rotation, c1_.rotation, u);
    for (std::size_t i = 0; i < 9; ++i) c.scale[i] = (1 - u) * c0_.scale[i] + u * c1_.scale[i];
    return c;
}

Transform AnimatedTransform::interpolate(double time) const {
    if (!animated_ || time <= t0_) return start_;
    if (time >= t1_) return end_;
    Matrix4 m = components(time).matrix();
    auto inv = inverse(m);
    // A scale that passes through zero between the two ends has no inverse there: the start stands in.
    if (!inv) return start_;
    return {m, *inv};
}

} // namespace illum
