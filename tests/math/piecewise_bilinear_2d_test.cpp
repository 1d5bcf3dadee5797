// The conditional bilinear warp of the RGL tables (math/piecewise_bilinear_2d.h): values at the nodes,
// the density integrates to 1, sample() and invert() are inverse maps, the samples follow the density
// (chi-square), and slices blend linearly in their parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "illum/math/piecewise_bilinear_2d.h"
#include "illum/util/error.h"
#include "stat_util.h"

namespace illum {
namespace {

// A smooth positive function on the unit square whose shape changes with a parameter p.
float shape(float x, float y, float p) { return 0.2f + std::pow(x, 1 + p) * (1 + std::sin(6 * y)) + p * y; }

PiecewiseBilinear2D make_table(int nx, int ny, const std::vector<float>& params, bool normalized) {
    std::vector<float> data;
    for (float p : params)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) data.push_back(shape(float(x) / (nx - 1), float(y) / (ny - 1), p));
    return PiecewiseBilinear2D(data, nx, ny, {params}, normalized);
}

TEST(PiecewiseBilinear2D, RawTableInterpolatesTheNodesAndBlendsSlices) {
    PiecewiseBilinear2D t = make_table(9, 7, {0, 1, 3}, false);
    for (float p : {0.0f, 1.0f, 3.0f})
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 9; ++x)
                EXPECT_NEAR(t.evaluate({x / 8.0f, y / 6.0f}, &p), shape(x / 8.0f, y / 6.0f, p), 1e-5f);
    // Between parameter nodes: the linear blend of the two slices; beyond them: the end slice.
    float p = 2, p1 = 1, p3 = 3, p9 = 9;
    Point2f q(0.37f, 0.61f);
    EXPECT_NEAR(t.evaluate(q, &p), 0.5f * (t.evaluate(q, &p1) + t.evaluate(q, &p3)), 1e-5f);
    EXPECT_FLOAT_EQ(t.evaluate(q, &p9), t.evaluate(q, &p3));
}

TEST(PiecewiseBilinear2D, DensityIntegratesToOneAndSamplingInvertsExactly) {
    PiecewiseBilinear2D t = make_table(9, 7, {0, 1, 3}, true);
    for (float p : {0.0f, 0.4f, 2.5f}) {
        // Midpoint rule on a grid fine enough that the bilinear pieces integrate to 1e-4.
        double sum = 0;
        const int n = 400;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) sum += t.evaluate({(i + 0.5f) / n, (j + 0.5f) / n}, &p);
        EXPECT_NEAR(sum / (n * n), 1.0, 1e-4) << p;
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> U(0, 1);
        for (int k = 0; k < 2000; ++k) {
            Point2f u(U(rng), U(rng));
            PiecewiseBilinear2D::Sample s = t.sample(u, &p);
            PiecewiseBilinear2D::Sample back = t.invert(s.p, &p);
            EXPECT_NEAR(back.p.x, u.x, 2e-4f);
            EXPECT_NEAR(back.p.y, u.y, 2e-4f);
            EXPECT_NEAR(s.pdf, t.evaluate(s.p, &p), 1e-4f * s.pdf);
            EXPECT_NEAR(back.pdf, s.pdf, 1e-4f * s.pdf);
        }
    }
}

TEST(PiecewiseBilinear2D, SamplesFollowTheDensity) {
    PiecewiseBilinear2D t = make_table(6, 5, {0, 1, 3}, true);
    float p = 1.7f;
    const int bins = 20, samples = 200000;
    std::vector<double> observed(bins * bins, 0), expected(bins * bins, 0);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> U(0, 1);
    for (int k = 0; k < samples; ++k) {
        Point2f q = t.sample({U(rng), U(rng)}, &p).p;
        int i = std::min(bins - 1, int(q.x * bins)), j = std::min(bins - 1, int(q.y * bins));
        observed[std::size_t(j * bins + i)] += 1;
    }
    const int sub = 16;
    for (int j = 0; j < bins; ++j)
        for (int i = 0; i < bins; ++i) {
            double s = 0;
            for (int b = 0; b < sub; ++b)
                for (int a = 0; a < sub; ++a)
                    s += t.evaluate({(i + (a + 0.5f) / sub) / bins, (j + (b + 0.5f) / sub) / bins}, &p);
            expected[std::size_t(j * bins + i)] = s / (sub * sub) / (bins * bins) * samples;
        }
    test::Chi2Result r = test::chi2_test(observed, expected);
    EXPECT_GT(r.p_value, 0.01) << "chi2 " << r.statistic << " dof " << r.dof;
}

TEST(PiecewiseBilinear2D, RejectsBadTables) {
    EXPECT_THROW(PiecewiseBilinear2D({1, 2, 3}, 2, 2, {}, false), Error);
    EXPECT_THROW(PiecewiseBilinear2D({1, 2, 3, 4}, 1, 4, {}, false), Error);
    EXPECT_THROW(PiecewiseBilinear2D({1, 2, 3, 4, 1, 2, 3, 4}, 2, 2, {{1, 1}}, false), Error);
    EXPECT_THROW(PiecewiseBilinear2D({1, -2, 3, 4}, 2, 2, {}, true), Error);
    // A slice that is zero everywhere is sampled uniformly.
    PiecewiseBilinear2D z({0, 0, 0, 0}, 2, 2, {}, true);
    EXPECT_NEAR(z.evaluate({0.3f, 0.8f}), 1.0f, 1e-6f);
}

} // namespace
} // namespace illum
