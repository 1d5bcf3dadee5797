// pbrt-v4's AnimatedTransform (math/animated_transform.h) against hand-computed cases: translation and
// scale interpolate linearly, a rotation turns at constant angular speed along the shorter arc (90° about z
// is 45° half-way, where a matrix lerp would also shrink the vector by cos 45°), the transform is clamped
// outside its times, and the decomposition T R S rebuilds every affine matrix it is given.
#include "illum/math/animated_transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace illum {
namespace {

void expect_point(Point3f p, double x, double y, double z, double tol = 1e-5) {
    EXPECT_NEAR(p.x, x, tol);
    EXPECT_NEAR(p.y, y, tol);
    EXPECT_NEAR(p.z, z, tol);
}

void expect_matrix(const Matrix4& a, const Matrix4& b, double tol = 1e-9) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(a(r, c), b(r, c), tol) << "row " << r << " column " << c;
}

TEST(AnimatedTransform, TranslationIsLinearAndClamped) {
    AnimatedTransform a(Transform::translate({0, 0, 0}), 1, Transform::translate({2, 4, 6}), 3);
    ASSERT_TRUE(a.is_animated());
    expect_point(a.interpolate(1.5)(Point3f{0, 0, 0}), 0.5, 1, 1.5);
    expect_point(a.interpolate(2)(Point3f{1, 1, 1}), 2, 3, 4);
    // Before the start and after the end: the start and end transforms themselves.
    EXPECT_EQ(a.interpolate(-10), a.start());
    EXPECT_EQ(a.interpolate(1), a.start());
    EXPECT_EQ(a.interpolate(3), a.end());
    EXPECT_EQ(a.interpolate(7), a.end());
}

TEST(AnimatedTransform, RotationOf90DegreesIs45HalfWay) {
    AnimatedTransform a(Transform(), 0, Transform::rotate(90, {0, 0, 1}), 1);
    double h = std::sqrt(0.5);
    expect_point(a.interpolate(0.5)(Point3f{1, 0, 0}), h, h, 0);
    // A quarter of the way: 22.5°, and the vector keeps its length (a matrix lerp gives 0.79 at t = 0.5).
    Point3f q = a.interpolate(0.25)(Point3f{2, 0, 0});
    expect_point(q, 2 * std::cos(kPiD / 8), 2 * std::sin(kPiD / 8), 0);
    // The inverse is the inverse.
    Transform t = a.interpolate(0.3);
    expect_matrix(t.matrix() * t.inverse_matrix(), Matrix4::identity(), 1e-12);
}

TEST(AnimatedTransform, RotationTakesTheShorterArc) {
    // 270° about z is -90°: pbrt-v4 (and this) turn the short way, reaching -45° half-way.
    AnimatedTransform a(Transform(), 0, Transform::rotate(270, {0, 0, 1}), 1);
    double h = std::sqrt(0.5);
    expect_point(a.interpolate(0.5)(Point3f{1, 0, 0}), h, -h, 0);
}

TEST(AnimatedTransform, ScaleIsLinear) {
    AnimatedTransform a(Transform::scale(1, 1, 1), 0, Transform::scale(3, 1, 0.5f), 1);
    expect_point(a.interpolate(0.5)(Point3f{1, 1, 1}), 2, 1, 0.75);
}

TEST(AnimatedTransform, TranslateRotateScaleInterpolatesEachPart) {
    // M = T R S with every part moving: half-way is T(mid) R(45°) S(mid).
    Transform start = Transform::translate({1, 0, 0}) * Transform::scale(1, 2, 1);
    Transform end =
        Transform::translate({3, 2, 0}) * Transform::rotate(90, {0, 0, 1}) * Transform::scale(3, 4, 1);
    AnimatedTransform a(start, 0, end, 2);
    Transform expected =
        Transform::translate({2, 1, 0}) * Transform::rotate(45, {0, 0, 1}) * Transform::scale(2, 3, 1);
    expect_matrix(a.interpolate(1).matrix(), expected.matrix(), 1e-6);
}

TEST(AnimatedTransform, DecompositionRebuildsTheMatrix) {
    for (const Transform& t :
         {Transform::translate({0.5f, -1, 2}) * Transform::rotate(40, {1, 2, 3}) *
              Transform::scale(1.5f, 0.7f, 1.2f),
          Transform::scale(2, 0.5f, 1) * Transform::rotate(70, {0, 1, 1}),  // S not diagonal
          Transform::rotate(30, {1, 0, 0}) * Transform::scale(-1, 1, 1)}) { // a mirror
        TransformComponents c = decompose(t.matrix());
        expect_matrix(c.matrix(), t.matrix(), 1e-9);
        // R is a rotation: its quaternion has unit length.
        EXPECT_NEAR(dot(c.rotation, c.rotation), 1, 1e-12);
        // S is symmetric (the polar factor).
        EXPECT_NEAR(c.scale[1], c.scale[3], 1e-9);
        EXPECT_NEAR(c.scale[2], c.scale[6], 1e-9);
        EXPECT_NEAR(c.scale[5], c.scale[7], 1e-9);
    }
}

TEST(AnimatedTransform, QuaternionRoundTrip) {
    Transform r = Transform::rotate(123, {0.3f, -1, 0.5f});
    Matrix3d m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[std::size_t(3 * i + j)] = r.matrix()(i, j);
    Matrix3d back = rotation_matrix(quaternion_from_rotation(m));
    for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(back[i], m[i], 1e-6);
}

TEST(AnimatedTransform, EqualTimesMakeAStep) {
    // pbrt-v4 allows TransformTimes t t: the start transform up to t, the end one after.
    AnimatedTransform a(Transform(), 0.5, Transform::translate({1, 0, 0}), 0.5);
    expect_point(a.interpolate(0.5)(Point3f{0, 0, 0}), 0, 0, 0);
    expect_point(a.interpolate(0.6)(Point3f{0, 0, 0}), 1, 0, 0);
}

TEST(AnimatedTransform, EqualTransformsDoNotMove) {
    Transform t = Transform::rotate(10, {0, 1, 0});
    AnimatedTransform a(t, 0, t, 1);
    EXPECT_FALSE(a.is_animated());
    EXPECT_EQ(a.interpolate(0.5), t);
}

} // namespace
} // namespace illum
