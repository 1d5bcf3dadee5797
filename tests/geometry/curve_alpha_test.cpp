// A curve's alpha (pbrt-v4's GeometricPrimitive alpha test, which curves pass through like every shape):
// the texture evaluated at the hit's (u, v), u along the Bézier segment and v across its width, keeps a hit
// with probability alpha by a hash of the ray. Checked by the covered area of parallel rays (binomial
// errors, as tests/geometry/curve_test.cpp): a constant alpha scales it, a texture that is 0 on half of u
// removes that half, for closest hits and shadow rays alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/curves.h"
#include "illum/param/param_set.h"
#include "param_support.h"

namespace illum {
namespace {

using test::floats;

// A straight flat curve along x from -2 to 2 (one Bézier segment, control points evenly spaced so u is
// linear in x: x = -2 + 4u), width 0.3, at z = 0.
std::unique_ptr<Curves> straight_curve() {
    ShapeDesc s;
    s.type = "curve";
    s.params.add(floats("P", {-2, 0, 0, -2.0 / 3, 0, 0, 2.0 / 3, 0, 0, 2, 0, 0}, ParamType::Point3));
    s.params.add(floats("width", {0.3}));
    Diagnostics diag;
    return create_curves(s, diag);
}
constexpr double kLength = 4, kWidth = 0.3;

class ConstantAlpha final : public FloatTexture {
public:
    explicit ConstantAlpha(float a) : a_(a) {}
    float evaluate(const TextureEvalContext&) const override { return a_; }

private:
    float a_;
};

// 0 where u < 1/2 (x < 0), 1 beyond; it records the largest and the mean |v - 1/2| it was asked at (one
// thread).
class HalfAlpha final : public FloatTexture {
public:
    float evaluate(const TextureEvalContext& c) const override {
        float off = std::abs(c.uv.y - 0.5f);
        max_v_offset = std::max(max_v_offset, off);
        sum_v_offset += off;
        ++calls;
        return c.uv.x < 0.5f ? 0.0f : 1.0f;
    }
    mutable float max_v_offset = 0;
    mutable double sum_v_offset = 0;
    mutable long calls = 0;
};

// Rays straight down through uniform points of [x0, x1] x [-0.5, 0.5]: the fraction that hit (closest
// hit) and the fraction that occlusion and shadow_crossings report blocked.
struct Fractions {
    double hit = 0, occluded = 0, blocked = 0;
};
Fractions shoot(const Accelerator& acc, float x0, float x1, int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> U(0, 1);
    Fractions f;
    for (int i = 0; i < n; ++i) {
        Ray ray{{x0 + (x1 - x0) * U(rng), -0.5f + U(rng), 10}, {0, 0, -1}, 20};
        SurfaceHit hit;
        f.hit += acc.intersect(ray, &hit);
        f.occluded += acc.occluded(ray);
        Accelerator::ShadowCrossings crossings;
        f.blocked += !acc.shadow_crossings(ray, &crossings);
    }
    f.hit /= n;
    f.occluded /= n;
    f.blocked /= n;
    return f;
}

// A fraction p of n rays over a rectangle of area A estimates the covered area p A, within 4.5 binomial
// standard errors.
void expect_area(double p, int n, double area, double expected, const char* what) {
    double se = std::sqrt(std::max(p * (1 - p), 1e-12) / n) * area;
    EXPECT_NEAR(p * area, expected, 4.5 * se + 1e-12) << what;
}

TEST(CurveAlpha, ConstantAlphaKeepsThatFractionOfHits) {
    ConstantAlpha alpha(0.4f);
    Accelerator acc;
    acc.add_curves(straight_curve(), nullptr, nullptr, &alpha);
    acc.commit();
    const int n = 100000;
    Fractions f = shoot(acc, -2.5f, 2.5f, n, 1);
    const double area = 5, expected = 0.4 * kLength * kWidth;
    std::printf("alpha 0.4: areas %.4f %.4f %.4f (expected %.4f)\n", f.hit * area, f.occluded * area,
                f.blocked * area, expected);
    expect_area(f.hit, n, area, expected, "closest hits");
    expect_area(f.occluded, n, area, expected, "occlusion");
    expect_area(f.blocked, n, area, expected, "shadow_crossings");
    // The decision is the ray's: a shadow ray along a camera ray's path decides as the camera ray did.
    EXPECT_EQ(f.hit, f.occluded);
    // Without alpha, the whole silhouette.
    Accelerator opaque;
    opaque.add_curves(straight_curve(), nullptr);
    opaque.commit();
    expect_area(shoot(opaque, -2.5f, 2.5f, n, 1).hit, n, area, kLength * kWidth, "opaque");
}

TEST(CurveAlpha, TextureZeroOnHalfOfTheCurveRemovesThatHalf) {
    HalfAlpha alpha;
    Accelerator acc;
    acc.add_curves(straight_curve(), nullptr, nullptr, &alpha);
    acc.commit();
    const int n = 50000;
    // x < 0 (u < 1/2): nothing, neither for closest hits nor for shadow rays.
    Fractions left = shoot(acc, -2.5f, -0.01f, n, 2);
    EXPECT_EQ(left.hit, 0);
    EXPECT_EQ(left.occluded, 0);
    EXPECT_EQ(left.blocked, 0);
    // x > 0: the whole width, 0.3 x 2 of the 2.5 x 1 rectangle.
    Fractions right = shoot(acc, 0.01f, 2.5f, n, 3);
    std::printf("half alpha: left %.4f, right %.4f (expected %.4f), max |v - 1/2| %.4f\n", left.hit * 2.49,
                right.hit * 2.49, (kLength / 2 - 0.01) * kWidth, alpha.max_v_offset);
    expect_area(right.hit, n, 2.49, (kLength / 2 - 0.01) * kWidth, "kept half");
    EXPECT_EQ(right.hit, right.occluded);
    EXPECT_EQ(right.hit, right.blocked);
    // v spans the width: 1/2 ± up to 1/2 at the edges, and rays uniform across the width meet it at |v - 1/2|
    // uniform on [0, 1/2] (mean 1/4; its standard error here is below 0.002), which they would not if the
    // filter placed the hit anywhere but on the ray at the candidate's distance.
    EXPECT_GT(alpha.max_v_offset, 0.45f);
    EXPECT_LE(alpha.max_v_offset, 0.5f);
    double mean_offset = alpha.sum_v_offset / double(alpha.calls);
    std::printf("mean |v - 1/2| %.4f over %ld evaluations\n", mean_offset, alpha.calls);
    EXPECT_NEAR(mean_offset, 0.25, 0.01);
}

TEST(CurveAlpha, CurvesWithDifferentAlphaAreNotMerged) {
    // Two curves of one material, one cut out: the opaque one keeps its silhouette.
    ConstantAlpha none(0.0f);
    Accelerator acc;
    acc.add_curves(straight_curve(), nullptr, nullptr, &none);
    auto moved = straight_curve();
    for (auto& c : moved->cp)
        for (Point3f& p : c) p.y += 1;
    acc.add_curves(std::move(moved), nullptr);
    acc.commit();
    Ray down{{0.5f, 0, 10}, {0, 0, -1}, 20};
    SurfaceHit hit;
    EXPECT_FALSE(acc.intersect(down, &hit));
    Ray other{{0.5f, 1, 10}, {0, 0, -1}, 20};
    EXPECT_TRUE(acc.intersect(other, &hit));
}

} // namespace
} // namespace illum
