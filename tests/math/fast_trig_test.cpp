// fast_atan and fast_tan against libm (in double) over their whole ranges: relative error below 4e-7 (3 ulp).
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
        if (exact != 0) worst = std::max(worst, std::abs(got - exact) / std::abs(exact));
        else EXPECT_EQ(got, 0.0);
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

} // namespace
} // namespace illum
