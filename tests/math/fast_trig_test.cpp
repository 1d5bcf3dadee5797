// fast_atan and fast_tan against libm (in double) over their whole ranges: relative error below 4e-7 (3 ulp);
// fast_sincos_quarter and fast_sincos_2pi: absolute error below 1.5e-7.
#include <gtest/gtest.h>

#include <cmath>

#include "illum/math/fast_trig.h"

namespace illum {
namespace {

TEST(FastTrig, AtanMatchesLibm) {
    double worst = 0;
    for (int i = -200000; i <= 200000; ++i) {
        // Logarithmically spaced from 1e-6 to 1e6, both signs, and zero.
        float x = i == 0 ? 0.0f : std::copysign(std::pow(10.0f, std::abs(i) / 200000.0f * 12 - 6), float(i));
        double exact = std::atan(double(x));
        double got = fast_atan(x);
        if (exact != 0)
            worst = std::max(worst, std::abs(got - exact) / std::abs(exact));
        else
            EXPECT_EQ(got, 0.0);
    }
    EXPECT_LT(worst, 4e-7);
    EXPECT_NEAR(fast_atan(INFINITY), M_PI / 2, 1e-7);
}

TEST(FastTrig, TanMatchesLibm) {
    double worst = 0;
    const float half_pi_below = std::nextafter(1.57079637f, 0.0f);
    for (int i = -400000; i <= 400000; ++i) {
        float x = half_pi_below * float(i) / 400000.0f;
        double exact = std::tan(double(x));
        double got = fast_tan(x);
        if (exact != 0) worst = std::max(worst, std::abs(got - exact) / std::abs(exact));
    }
    EXPECT_LT(worst, 4e-7);
    EXPECT_GT(fast_tan(half_pi_below), 1e7f); // positive near the pole, as equiangular sampling needs
}

TEST(FastTrig, SinCosMatchLibm) {
    double worst = 0;
    for (int i = -200000; i <= 200000; ++i) {
        float a = 0.785398163f * float(i) / 200000.0f;
        float s, c;
        fast_sincos_quarter(a, &s, &c);
        worst = std::max({worst, std::abs(s - std::sin(double(a))), std::abs(c - std::cos(double(a)))});
    }
    EXPECT_LT(worst, 1.5e-7);
    worst = 0;
    for (int i = 0; i <= 800000; ++i) {
        float u = float(i) / 800000.0f; // every quarter turn, its ends and the rounding points between
        float s, c;
        fast_sincos_2pi(u, &s, &c);
        double phi = 2 * M_PI * double(u);
        worst = std::max({worst, std::abs(s - std::sin(phi)), std::abs(c - std::cos(phi))});
    }
    EXPECT_LT(worst, 1.5e-7);
    float s, c;
    fast_sincos_2pi(0.25f, &s, &c);
    EXPECT_EQ(s, 1.0f);
    EXPECT_EQ(c, 0.0f);
}

} // namespace
} // namespace illum
