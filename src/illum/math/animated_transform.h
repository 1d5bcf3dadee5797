// A transform that moves during the shutter interval (pbrt-v4's AnimatedTransform): given at a start
// and an end time, it is decomposed into translation T, rotation R and scale S (M = T R S, the polar
// decomposition of the 3x3 part: R orthogonal, S symmetric; Shoemake & Duff, "Matrix animation and polar
// decomposition", Graphics Interface 1992), and in between T and S are interpolated linearly and R by
// spherical linear interpolation of its quaternion along the shorter arc, so a rotation turns at constant
// angular speed (a matrix lerp would shrink it). Before the start time it is the start transform, after
// the end time the end transform.
#pragma once

#include <array>

#include "illum/math/matrix3.h"
#include "illum/math/quaternion.h"
#include "illum/math/transform.h"

namespace illum {

// M = T R S of an affine transform: translation, rotation (a unit quaternion) and a 3x3 scale.
struct TransformComponents {
    std::array<double, 3> translation{};
    Quaternion rotation;
    Matrix3d scale{1, 0, 0, 0, 1, 0, 0, 0, 1};

    Matrix4 matrix() const; // T R S
};

// Whether the bottom row of m is (0, 0, 0, 1): only affine transforms can be decomposed.
bool is_affine(const Matrix4& m);

// The polar decomposition M = T R S of an affine transform (R from the iteration R <- (R + R^-T) / 2,
// Higham 1986, S = Rᵀ M). A reflection (det M < 0) is taken into S: R = -R_polar, S = -S_polar, so R is
// always a rotation.
TransformComponents decompose(const Matrix4& m);

class AnimatedTransform {
public:
    AnimatedTransform() = default;
    explicit AnimatedTransform(const Transform& t) : start_(t), end_(t) {}
    // start at start_time, end at end_time (start_time <= end_time; equal times make a step); both affine.
    AnimatedTransform(const Transform& start, double start_time, const Transform& end, double end_time);

    bool is_animated() const { return animated_; }
    const Transform& start() const { return start_; }
    const Transform& end() const { return end_; }
    double start_time() const { return t0_; }
    double end_time() const { return t1_; }

    // The transform at `time` (clamped to the start and end times).
    Transform interpolate(double time) const;
    // Its components T, R, S at `time` (clamped), the rotation on the arc from the start's quaternion.
    TransformComponents components(double time) const;

private:
    Transform start_, end_;
    double t0_ = 0, t1_ = 1;
    bool animated_ = false;
    TransformComponents c0_, c1_;
};

} // namespace illum
