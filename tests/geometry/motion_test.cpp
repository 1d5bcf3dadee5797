// Moving geometry through the accelerator (Embree instance motion blur, geometry/motion_steps.h): rays at
// a given time hit the shape where pbrt-v4's AnimatedTransform puts it then, hits carry their time, and
// the time steps handed to Embree reproduce the interpolated transform.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/motion_steps.h"
#include "illum/geometry/sphere.h"

namespace illum {
namespace {

// An accelerator with shutter [0, 1] holding a prototype of a unit sphere at its origin; *proto is its id.
std::unique_ptr<Accelerator> sphere_prototype(std::uint32_t* proto) {
    auto acc = std::make_unique<Accelerator>();
    acc->set_shutter(0, 1);
    *proto = acc->begin_prototype();
    acc->add_shape(std::make_unique<SphereShape>(Transform(), 1.0f, -1.0f, 1.0f, 2 * kPi, false), nullptr,
                   nullptr);
    acc->end_prototype();
    return acc;
}

// A unit sphere at the origin of its own prototype, placed by `motion`; shutter [0, 1].
std::unique_ptr<Accelerator> moving_sphere(const AnimatedTransform& motion) {
    std::uint32_t proto;
    auto acc = sphere_prototype(&proto);
    acc->add_moving_instance(proto, motion);
    acc->commit();
    return acc;
}

// The distance along a ray straight down from z = 10 at (x, y), at `time`; infinity for a miss.
float drop(const Accelerator& acc, float x, float y, float time, SurfaceHit* hit = nullptr) {
    Ray r{{x, y, 10}, {0, 0, -1}, kInfinity};
    r.time = time;
    SurfaceHit h;
    if (!acc.intersect(r, &h)) return kInfinity;
    if (hit) *hit = h;
    return h.t;
}

TEST(Motion, TranslatingSphereIsWhereTheTimeSays) {
    auto acc = moving_sphere(
        AnimatedTransform(Transform::translate({-4, 0, 0}), 0, Transform::translate({4, 0, 0}), 1));
    for (float t : {0.0f, 0.25f, 0.5f, 0.8f, 1.0f}) {
        float cx = -4 + 8 * t;
        SurfaceHit hit;
        EXPECT_NEAR(drop(*acc, cx, 0, t, &hit), 9, 1e-4) << "time " << t; // the top of the sphere, z = 1
        EXPECT_NEAR(hit.p.x, cx, 1e-4);
        EXPECT_NEAR(hit.p.z, 1, 1e-4);
        EXPECT_NEAR(hit.n.z, 1, 1e-4);
        EXPECT_EQ(hit.time, t);
        // Where the sphere was not then: a miss (1.5 radii away).
        EXPECT_EQ(drop(*acc, cx + 1.5f, 0, t), kInfinity);
    }
    // A time outside the shutter is clamped to it.
    EXPECT_NEAR(drop(*acc, 4, 0, 3.0f), 9, 1e-4);
}

TEST(Motion, RotatingInstanceTurnsAtConstantSpeed) {
    // The sphere sits 3 units along the instance's x axis, scaled to an ellipsoid with semi-axis 2 along
    // that x and 0.5 across; the instance turns 90° about z. pbrt-v4 interpolates the rotation by slerp: at
    // t = 1/3 the long axis points at 30°, and the ellipsoid's centre moves with it (the translation is
    // the rotated offset, linear in t between (3,0,0) and (0,3,0)).
    Transform offset = Transform::translate({3, 0, 0}) * Transform::scale(2, 0.5f, 1);
    AnimatedTransform motion(offset, 0, Transform::rotate(90, {0, 0, 1}) * offset, 1);
    auto acc = moving_sphere(motion);
    double t = 1.0 / 3, a = kPiD / 6;
    // M = R(90°) T S = T' R S with T' = R(90°)(3,0,0) = (0,3,0): pbrt-v4 moves the centre linearly.
    double cx = 3 * (1 - t), cy = 3 * t;
    // Along the long axis at 1.9 from the centre: inside the ellipsoid only if it points at 30°.
    double r = 1.9;
    float x = float(cx + r * std::cos(a)), y = float(cy + r * std::sin(a));
    SurfaceHit hit;
    float d = drop(*acc, x, y, float(t), &hit);
    ASSERT_LT(d, 10);
    // The hit is carried back to the world by the transform of that instant: it lies on the ray.
    EXPECT_NEAR(hit.p.x, x, 1e-4);
    EXPECT_NEAR(hit.p.y, y, 1e-4);
    EXPECT_NEAR(hit.p.z, 10 - d, 1e-4);
    // On the ellipsoid x²/4 + y²/0.25 + z² = 1 in its own frame, turned by 30°: z = √(1 - 0.95²).
    EXPECT_NEAR(hit.p.z, std::sqrt(1 - 0.95 * 0.95), 1e-3);
    // At 40° or 20° the same distance is outside (the half-width there is about 0.5 / sin(10°) ... < 1.9).
    for (double off : {-10.0, 10.0}) {
        double b = a + off * kPiD / 180;
        EXPECT_EQ(drop(*acc, float(cx + r * std::cos(b)), float(cy + r * std::sin(b)), float(t)), kInfinity)
            << "angle " << b * 180 / kPiD;
    }
    // The height of the hit at the centre is the sphere's z extent (scale 1 along z).
    EXPECT_NEAR(drop(*acc, float(cx), float(cy), float(t)), 9, 1e-4);
}

TEST(Motion, TwoExactStepsForTranslateRotateScale) {
    AnimatedTransform m(
        Transform::translate({1, 2, 3}), 0,
        Transform::translate({-1, 0, 5}) * Transform::rotate(120, {0, 1, 1}) * Transform::scale(2, 3, 4), 1);
    std::vector<TransformComponents> s = motion_steps(m, 0, 1);
    ASSERT_EQ(s.size(), 2u);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            EXPECT_NEAR(s[0].matrix()(i, j), m.start().matrix()(i, j), 1e-6);
            EXPECT_NEAR(s[1].matrix()(i, j), m.end().matrix()(i, j), 1e-6);
        }
    // A shutter inside the motion: still two steps, at the shutter's ends.
    s = motion_steps(m, 0.25, 0.5);
    ASSERT_EQ(s.size(), 2u);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(s[1].matrix()(i, j), m.interpolate(0.5).matrix()(i, j), 1e-6);
}

TEST(Motion, ManyStepsWhenTheMotionStopsInsideTheShutterOrScalesAfterRotating) {
    // Motion over [0.2, 0.6] in a shutter [0, 1]: each step is the clamped transform at its time.
    AnimatedTransform m(Transform(), 0.2, Transform::translate({10, 0, 0}), 0.6);
    std::vector<TransformComponents> s = motion_steps(m, 0, 1);
    ASSERT_EQ(int(s.size()), kManyMotionSteps);
    for (int i = 0; i < kManyMotionSteps; ++i) {
        double t = double(i) / (kManyMotionSteps - 1);
        EXPECT_NEAR(s[std::size_t(i)].translation[0], m.interpolate(t).matrix()(0, 3), 1e-9);
    }
    // A scale after a rotation has a non-diagonal polar factor: Embree's form R U (U upper triangular)
    // of each step still rebuilds the transform.
    AnimatedTransform k(Transform(), 0, Transform::scale(3, 1, 1) * Transform::rotate(60, {0, 0, 1}), 1);
    s = motion_steps(k, 0, 1);
    ASSERT_EQ(int(s.size()), kManyMotionSteps);
    for (int i : {1, 20, 64}) {
        double t = double(i) / (kManyMotionSteps - 1);
        const TransformComponents& c = s[std::size_t(i)];
        EXPECT_NEAR(c.scale[3], 0, 1e-12);
        EXPECT_NEAR(c.scale[6], 0, 1e-12);
        EXPECT_NEAR(c.scale[7], 0, 1e-12);
        for (int r = 0; r < 3; ++r)
            for (int col = 0; col < 4; ++col)
                EXPECT_NEAR(c.matrix()(r, col), k.interpolate(t).matrix()(r, col), 1e-9);
    }
}

// A moving shape in an object instance: the motion is the instance's transform times the shape's, at each
// time (pbrt-v4 nests the shape's AnimatedPrimitive in the instance's primitive).
void expect_steps_are_the_product(const std::vector<TransformComponents>& s, const AnimatedTransform& outer,
                                  const AnimatedTransform& inner) {
    for (std::size_t i = 0; i < s.size(); ++i) {
        double t = s.size() == 1 ? 0 : double(i) / double(s.size() - 1);
        Matrix4 want = (outer.interpolate(t) * inner.interpolate(t)).matrix();
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(s[i].matrix()(r, c), want(r, c), 1e-9) << "step " << i;
    }
}

TEST(Motion, NestedMotionTakesTwoStepsWhereTheyAreExact) {
    AnimatedTransform inner(
        Transform::translate({1, 0, 0}), 0,
        Transform::translate({0, 2, 0}) * Transform::rotate(100, {0, 0, 1}) * Transform::scale(1, 2, 3), 1);
    // A still similarity around it: R_w (T R S) = (R_w T)(R_w R) S, interpolated as Embree does.
    AnimatedTransform still(Transform::translate({5, -1, 2}) * Transform::rotate(30, {1, 1, 0}) *
                            Transform::scale(2, 2, 2));
    std::vector<TransformComponents> s = motion_steps(still, inner, 0, 1);
    EXPECT_EQ(s.size(), 2u);
    expect_steps_are_the_product(s, still, inner);
    // Two translations add.
    AnimatedTransform slide(Transform::translate({0, 0, -3}), 0, Transform::translate({4, 0, 0}), 1);
    AnimatedTransform shift(Transform(), 0, Transform::translate({0, 1, 0}), 1);
    s = motion_steps(slide, shift, 0, 1);
    EXPECT_EQ(s.size(), 2u);
    expect_steps_are_the_product(s, slide, shift);
}

TEST(Motion, NestedMotionTakesManyStepsOtherwise) {
    AnimatedTransform inner(Transform(), 0, Transform::rotate(90, {0, 0, 1}), 1);
    // A non-uniform scale around a rotation: the product's rotation does not turn at constant speed.
    AnimatedTransform squash(Transform::scale(4, 1, 1));
    std::vector<TransformComponents> s = motion_steps(squash, inner, 0, 1);
    EXPECT_EQ(int(s.size()), kManyMotionSteps);
    expect_steps_are_the_product(s, squash, inner);
    // Two rotations about different axes: their product is no slerp.
    AnimatedTransform tumble(Transform(), 0, Transform::rotate(90, {1, 0, 0}), 1);
    s = motion_steps(tumble, inner, 0, 1);
    EXPECT_EQ(int(s.size()), kManyMotionSteps);
    expect_steps_are_the_product(s, tumble, inner);
    // The inner motion stops inside the shutter.
    AnimatedTransform early(Transform(), 0, Transform::translate({1, 0, 0}), 0.5);
    s = motion_steps(AnimatedTransform(Transform::rotate(10, {0, 1, 0})), early, 0, 1);
    EXPECT_EQ(int(s.size()), kManyMotionSteps);
    expect_steps_are_the_product(s, AnimatedTransform(Transform::rotate(10, {0, 1, 0})), early);
}

TEST(Motion, MovingShapeInAMovingInstanceIsWhereBothSay) {
    // A unit sphere sliding along the instance's y, in an instance turned 90° about z (its y is the world's
    // -x) that itself slides along the world's y.
    std::uint32_t proto;
    auto acc = sphere_prototype(&proto);
    AnimatedTransform inner(Transform::translate({0, -3, 0}), 0, Transform::translate({0, 3, 0}), 1);
    AnimatedTransform outer(Transform::rotate(90, {0, 0, 1}), 0,
                            Transform::translate({0, 4, 0}) * Transform::rotate(90, {0, 0, 1}), 1);
    acc->add_moving_instance(proto, outer, inner);
    acc->commit();
    for (float t : {0.0f, 0.3f, 0.75f, 1.0f}) {
        // The centre: the instance's (0, -3 + 6t) turned to (3 - 6t, 0), then moved by (0, 4t).
        float cx = 3 - 6 * t, cy = 4 * t;
        SurfaceHit hit;
        EXPECT_NEAR(drop(*acc, cx, cy, t, &hit), 9, 1e-4) << "time " << t;
        EXPECT_NEAR(hit.p.x, cx, 1e-4);
        EXPECT_NEAR(hit.p.y, cy, 1e-4);
        EXPECT_EQ(drop(*acc, cx + 1.2f, cy, t), kInfinity);
        EXPECT_EQ(drop(*acc, cx, cy - 1.2f, t), kInfinity);
    }
}

} // namespace
} // namespace illum
