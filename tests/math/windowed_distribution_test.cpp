// WindowedDistribution2D: the window's integral against a direct sum over cut cells, samples inside the
// window, the returned pdf against pdf(), and a chi-square test of the samples against the density.
#include <gtest/gtest.h>

#include <vector>

#include "illum/math/rng.h"
#include "illum/math/windowed_distribution.h"
#include "math/stat_util.h"

namespace illum {
namespace {

const int kNu = 7, kNv = 5;

std::vector<float> weights() {
    std::vector<float> w(kNu * kNv);
    for (int j = 0; j < kNv; ++j)
        for (int i = 0; i < kNu; ++i) w[j * kNu + i] = float((i * 3 + j * 5) % 7); // zeros among them
    return w;
}

// ∫ over [lo, hi] by summing each cell's weight times its overlap with the window.
double direct_integral(const std::vector<float>& w, Point2f lo, Point2f hi) {
    double sum = 0;
    for (int j = 0; j < kNv; ++j)
        for (int i = 0; i < kNu; ++i) {
            double ox = std::max(0.0, std::min<double>(hi.x, (i + 1.0) / kNu) -
                                          std::max<double>(lo.x, double(i) / kNu));
            double oy = std::max(0.0, std::min<double>(hi.y, (j + 1.0) / kNv) -
                                          std::max<double>(lo.y, double(j) / kNv));
            sum += w[j * kNu + i] * ox * oy;
        }
    return sum;
}

TEST(WindowedDistribution2D, IntegralOverAnyWindow) {
    auto w = weights();
    WindowedDistribution2D d(w, kNu, kNv);
    PCG32 rng(3);
    for (int k = 0; k < 200; ++k) {
        float a = rng.uniform_float(), b = rng.uniform_float(), c = rng.uniform_float(),
              e = rng.uniform_float();
        Point2f lo{std::min(a, b), std::min(c, e)}, hi{std::max(a, b), std::max(c, e)};
        EXPECT_NEAR(d.integral(lo, hi), direct_integral(w, lo, hi), 1e-5);
    }
    EXPECT_NEAR(d.integral({0, 0}, {1, 1}), direct_integral(w, {0, 0}, {1, 1}), 1e-6);
}

// Samples of a cut window: inside it, with pdf() equal to the returned density, and distributed as the
// density over the cells the window cuts (chi-square, 1% significance).
TEST(WindowedDistribution2D, SamplesFollowTheDensityWithinTheWindow) {
    auto w = weights();
    WindowedDistribution2D d(w, kNu, kNv);
    const Point2f lo{0.13f, 0.27f}, hi{0.81f, 0.93f};
    const double total = direct_integral(w, lo, hi);
    std::vector<double> observed(kNu * kNv, 0), expected(kNu * kNv, 0);
    const int n = 200000;
    PCG32 rng(11);
    for (int k = 0; k < n; ++k) {
        float pdf = 0;
        auto p = d.sample({rng.uniform_float(), rng.uniform_float()}, lo, hi, &pdf);
        ASSERT_TRUE(p);
        ASSERT_GE(p->x, lo.x);
        ASSERT_LE(p->x, hi.x);
        ASSERT_GE(p->y, lo.y);
        ASSERT_LE(p->y, hi.y);
        EXPECT_NEAR(pdf, d.pdf(*p, lo, hi), 1e-5f * pdf);
        int i = std::min(int(p->x * kNu), kNu - 1), j = std::min(int(p->y * kNv), kNv - 1);
        EXPECT_GT(w[j * kNu + i], 0) << "a sample in a cell of zero weight";
        EXPECT_NEAR(pdf, w[j * kNu + i] / total, 1e-4 * pdf);
        observed[j * kNu + i] += 1;
    }
    for (int j = 0; j < kNv; ++j)
        for (int i = 0; i < kNu; ++i) {
            Point2f clo{std::max(lo.x, float(i) / kNu), std::max(lo.y, float(j) / kNv)};
            Point2f chi{std::min(hi.x, float(i + 1) / kNu), std::min(hi.y, float(j + 1) / kNv)};
            if (chi.x > clo.x && chi.y > clo.y)
                expected[j * kNu + i] = n * direct_integral(w, clo, chi) / total;
        }
    auto r = test::chi2_test(observed, expected);
    EXPECT_GT(r.p_value, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
    // Outside the window the density is zero.
    EXPECT_EQ(d.pdf({0.05f, 0.5f}, lo, hi), 0);
}

TEST(WindowedDistribution2D, EmptyWindowGivesNoSample) {
    auto w = weights();
    WindowedDistribution2D d(w, kNu, kNv);
    float pdf = 0;
    EXPECT_FALSE(d.sample({0.5f, 0.5f}, {0.3f, 0.3f}, {0.3f, 0.6f}, &pdf)); // zero width
    std::vector<float> zeros(kNu * kNv, 0.0f);
    WindowedDistribution2D z(zeros, kNu, kNv);
    EXPECT_FALSE(z.sample({0.5f, 0.5f}, {0, 0}, {1, 1}, &pdf));
}

} // namespace
} // namespace illum
