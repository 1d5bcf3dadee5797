// Distribution1D, Distribution2D and AliasTable: sampling reproduces the weights (chi-square at 1%),
// densities integrate to 1, remapped uniforms are uniform, zero weights are never sampled, and all-zero
// input falls back to uniform.
#include "illum/math/distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include "illum/math/rng.h"
#include "math/stat_util.h"

namespace illum {
namespace {

using test::chi2_test;
using test::Chi2Result;

constexpr double kSignificance = 0.01;
constexpr int kSamples = 200000;

::testing::AssertionResult chi2_ok(const Chi2Result& r) {
    std::printf("  chi2 %.1f dof %d p %.3f\n", r.statistic, r.dof, r.p_value);
    if (r.p_value >= kSignificance) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value;
}

// Weights with zeros at both ends and inside, a dominant entry and tiny ones.
std::vector<float> test_weights() {
    std::vector<float> w = {0, 0, 1, 3, 0, 0.5f, 10, 2, 0, 0, 0.01f, 4, 1, 7, 0.2f, 0};
    PCG32 rng(99);
    for (int i = 0; i < 48; ++i) w.push_back(rng.uniform_float() < 0.2f ? 0.0f : 5 * rng.uniform_float());
    w.push_back(0);
    return w;
}

double sum_of(const std::vector<float>& w) { return std::accumulate(w.begin(), w.end(), 0.0); }

// Chi-square of 1D values in [0, 1) over n equal bins against the uniform distribution.
Chi2Result uniformity(const std::vector<float>& values, int n = 50) {
    std::vector<double> observed(static_cast<size_t>(n)),
        expected(static_cast<size_t>(n), double(values.size()) / n);
    for (float v : values) observed[size_t(std::clamp(int(v * n), 0, n - 1))] += 1;
    return chi2_test(observed, expected);
}

TEST(Distribution1D, DiscreteSamplingMatchesWeights) {
    auto w = test_weights();
    Distribution1D d(w);
    ASSERT_EQ(d.size(), int(w.size()));
    EXPECT_FALSE(d.is_degenerate());
    const double sum = sum_of(w);
    EXPECT_NEAR(d.integral(), sum / double(w.size()), 1e-6 * sum);
    for (int i = 0; i < d.size(); ++i) EXPECT_NEAR(d.pmf(i), w[size_t(i)] / sum, 1e-7);

    std::vector<double> observed(w.size()), expected(w.size());
    std::vector<float> remapped;
    PCG32 rng(1);
    int pmf_mismatch = 0;
    for (int s = 0; s < kSamples; ++s) {
        float pmf, ur;
        int i = d.sample_discrete(rng.uniform_float(), &pmf, &ur);
        observed[size_t(i)] += 1;
        pmf_mismatch += std::abs(pmf - d.pmf(i)) > 1e-7f;
        EXPECT_GE(ur, 0.0f);
        EXPECT_LT(ur, 1.0f);
        if (i == 6) remapped.push_back(ur); // the remapped u within one outcome is uniform
    }
    for (size_t i = 0; i < w.size(); ++i) expected[i] = kSamples * w[i] / sum; // zero weight: must be empty
    EXPECT_EQ(pmf_mismatch, 0);
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
    EXPECT_TRUE(chi2_ok(uniformity(remapped, 20)));
}

TEST(Distribution1D, ContinuousSamplingMatchesDensity) {
    auto w = test_weights();
    Distribution1D d(w);
    const int n = d.size(), sub = 4; // histogram bins: 4 per piece, so uniformity within pieces is tested too
    std::vector<double> observed(static_cast<size_t>(n * sub)), expected(static_cast<size_t>(n * sub));
    PCG32 rng(2);
    int pdf_mismatch = 0, offset_mismatch = 0;
    for (int s = 0; s < kSamples; ++s) {
        float pdf;
        int off;
        float x = d.sample_continuous(rng.uniform_float(), &pdf, &off);
        ASSERT_GE(x, 0.0f);
        ASSERT_LT(x, 1.0f);
        pdf_mismatch += pdf != d.pdf(x) || !(pdf > 0);
        offset_mismatch += off != std::min(int(double(x) * n), n - 1);
        observed[size_t(std::min(int(double(x) * n * sub), n * sub - 1))] += 1;
    }
    EXPECT_EQ(pdf_mismatch, 0);
    EXPECT_EQ(offset_mismatch, 0);
    for (int b = 0; b < n * sub; ++b)
        expected[size_t(b)] = kSamples * double(d.pdf((b + 0.5f) / float(n * sub))) / double(n * sub);
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));

    // The density integrates to 1 (exactly, by the midpoint rule on a piecewise-constant function).
    double integral = 0;
    for (int i = 0; i < n; ++i) integral += d.pdf((i + 0.5f) / float(n)) / double(n);
    EXPECT_NEAR(integral, 1.0, 1e-6);
}

TEST(Distribution1D, EdgesAndMonotonicity) {
    auto w = test_weights();
    Distribution1D d(w);
    // u = 0, the largest float below 1, and u = 1 (clamped) land on non-zero pieces: the first and last.
    EXPECT_EQ(d.sample_discrete(0.0f), 2);
    EXPECT_EQ(d.sample_discrete(0x1.fffffep-1f), int(w.size()) - 2);
    EXPECT_EQ(d.sample_discrete(1.0f), int(w.size()) - 2);
    EXPECT_LT(d.sample_continuous(1.0f), 1.0f);
    EXPECT_GE(d.sample_continuous(0.0f), 2.0f / float(w.size()));
    // Monotone in u, never on a zero-weight piece, over a fine sweep.
    float prev = -1;
    int zero_hits = 0;
    for (int k = 0; k <= 100000; ++k) {
        float u = std::min(k / 100000.0f, 0x1.fffffep-1f);
        int off;
        float x = d.sample_continuous(u, nullptr, &off);
        EXPECT_GE(x, prev);
        prev = x;
        zero_hits += w[size_t(off)] == 0;
    }
    EXPECT_EQ(zero_hits, 0);
}

TEST(Distribution1D, AllZeroIsUniform) {
    std::vector<float> w(10, 0.0f);
    w[3] = -1; // negative and NaN count as zero
    w[4] = std::nanf("");
    Distribution1D d(w);
    EXPECT_TRUE(d.is_degenerate());
    EXPECT_EQ(d.integral(), 0.0f);
    for (int i = 0; i < 10; ++i) EXPECT_FLOAT_EQ(d.pmf(i), 0.1f);
    EXPECT_EQ(d.pdf(0.37f), 1.0f);
    float pdf;
    EXPECT_FLOAT_EQ(d.sample_continuous(0.37f, &pdf), 0.37f);
    EXPECT_EQ(pdf, 1.0f);
    std::vector<double> observed(10), expected(10, kSamples / 10.0);
    PCG32 rng(3);
    for (int s = 0; s < kSamples; ++s) observed[size_t(d.sample_discrete(rng.uniform_float()))] += 1;
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
    EXPECT_FALSE(Distribution1D(test_weights()).is_degenerate());
}

TEST(Distribution1D, LargeTable) {
    // One million pieces, weights spanning 12 orders of magnitude: pmf sums to 1 and sampling is exact at
    // the CDF level (the double CDF keeps every piece's width).
    const int n = 1 << 20;
    std::vector<float> w(static_cast<size_t>(n));
    PCG32 rng(4);
    for (auto& x : w) x = std::pow(10.0f, -12 * rng.uniform_float());
    Distribution1D d(w);
    double total = 0;
    for (int i = 0; i < n; ++i) total += d.pmf(i);
    EXPECT_NEAR(total, 1.0, 1e-6);
    // Coarse histogram: 64 groups of 16384 pieces.
    std::vector<double> observed(64), expected(64);
    for (int i = 0; i < n; ++i) expected[size_t(i >> 14)] += d.pmf(i) * kSamples;
    for (int s = 0; s < kSamples; ++s) observed[size_t(d.sample_discrete(rng.uniform_float()) >> 14)] += 1;
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
}

// ---------------------------------------------------------------------------------------------------------

TEST(Distribution2D, SamplingMatchesWeights) {
    const int nu = 12, nv = 7;
    std::vector<float> w(static_cast<size_t>(nu * nv));
    PCG32 rng(5);
    for (int v = 0; v < nv; ++v)
        for (int u = 0; u < nu; ++u)
            w[size_t(v * nu + u)] =
                (v == 2) ? 0.0f : (u == 5 ? 0.0f : float(1 + u * v) * rng.uniform_float());
    Distribution2D d(w, nu, nv);
    EXPECT_FALSE(d.is_degenerate());
    const double sum = sum_of(w);

    // Cells subdivided 2 x 2 so that uniformity within a cell is tested.
    const int su = 2 * nu, sv = 2 * nv;
    std::vector<double> observed(static_cast<size_t>(su * sv)), expected(static_cast<size_t>(su * sv));
    int pdf_mismatch = 0;
    for (int s = 0; s < kSamples; ++s) {
        float pdf;
        Point2f p = d.sample({rng.uniform_float(), rng.uniform_float()}, &pdf);
        ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
        pdf_mismatch += std::abs(pdf - d.pdf(p)) > 1e-5f * pdf || !(pdf > 0);
        observed[size_t(std::min(int(p.y * sv), sv - 1) * su + std::min(int(p.x * su), su - 1))] += 1;
    }
    EXPECT_EQ(pdf_mismatch, 0);
    for (int v = 0; v < sv; ++v)
        for (int u = 0; u < su; ++u)
            expected[size_t(v * su + u)] = kSamples * w[size_t((v / 2) * nu + u / 2)] / sum / 4;
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));

    // pdf integrates to 1 and equals weight / mean weight.
    double integral = 0;
    for (int v = 0; v < nv; ++v)
        for (int u = 0; u < nu; ++u) {
            Point2f c{(u + 0.5f) / nu, (v + 0.5f) / nv};
            integral += d.pdf(c) / double(nu * nv);
            EXPECT_NEAR(d.pdf(c), w[size_t(v * nu + u)] / (sum / (nu * nv)), 1e-5);
        }
    EXPECT_NEAR(integral, 1.0, 1e-6);
}

TEST(Distribution2D, AllZeroIsUniform) {
    std::vector<float> w(6 * 4, 0.0f);
    Distribution2D d(w, 6, 4);
    EXPECT_TRUE(d.is_degenerate());
    float pdf;
    Point2f p = d.sample({0.3f, 0.8f}, &pdf);
    EXPECT_EQ(pdf, 1.0f);
    EXPECT_NEAR(p.x, 0.3f, 1e-6f);
    EXPECT_NEAR(p.y, 0.8f, 1e-6f);
    EXPECT_EQ(d.pdf({0.5f, 0.5f}), 1.0f);
}

// ---------------------------------------------------------------------------------------------------------

TEST(AliasTable, PmfAndSampling) {
    auto w = test_weights();
    AliasTable t(w);
    ASSERT_EQ(t.size(), int(w.size()));
    const double sum = sum_of(w);
    for (int i = 0; i < t.size(); ++i) EXPECT_NEAR(t.pmf(i), w[size_t(i)] / sum, 1e-7);

    std::vector<double> observed(w.size()), expected(w.size());
    std::vector<float> remapped;
    PCG32 rng(6);
    int pmf_mismatch = 0;
    for (int s = 0; s < kSamples; ++s) {
        float pmf, ur;
        int i = t.sample(rng.uniform_float(), &pmf, &ur);
        observed[size_t(i)] += 1;
        pmf_mismatch += pmf != t.pmf(i);
        EXPECT_GE(ur, 0.0f);
        EXPECT_LT(ur, 1.0f);
        if (i == 6) remapped.push_back(ur);
    }
    for (size_t i = 0; i < w.size(); ++i) expected[i] = kSamples * w[i] / sum;
    EXPECT_EQ(pmf_mismatch, 0);
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
    EXPECT_TRUE(chi2_ok(uniformity(remapped, 20)));

    // Exhaustive: the table's implied probabilities (q_i + incoming alias mass) / n equal the pmf.
    // A fine uniform sweep of u measures them to within 1/sweep.
    const int sweep = 1 << 22;
    std::vector<double> hits(w.size());
    for (int k = 0; k < sweep; ++k) hits[size_t(t.sample((k + 0.5f) / float(sweep)))] += 1;
    for (size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(hits[i] / sweep, w[i] / sum, 2.0 * w.size() / sweep);
}

TEST(AliasTable, AllZeroIsUniform) {
    std::vector<float> w(8, 0.0f);
    AliasTable t(w);
    EXPECT_TRUE(t.is_degenerate());
    for (int i = 0; i < 8; ++i) EXPECT_FLOAT_EQ(t.pmf(i), 0.125f);
    std::vector<double> observed(8), expected(8, kSamples / 8.0);
    PCG32 rng(7);
    for (int s = 0; s < kSamples; ++s) observed[size_t(t.sample(rng.uniform_float()))] += 1;
    EXPECT_TRUE(chi2_ok(chi2_test(observed, expected)));
}

// Negative control: the chi-square check rejects a distribution off by a few percent in one entry.
TEST(DistributionChecks, RejectWrongWeights) {
    auto w = test_weights();
    Distribution1D d(w);
    auto wrong = w;
    wrong[6] *= 1.05f;
    const double sum = sum_of(wrong);
    std::vector<double> observed(w.size()), expected(w.size());
    PCG32 rng(1);
    for (int s = 0; s < 4 * kSamples; ++s) observed[size_t(d.sample_discrete(rng.uniform_float()))] += 1;
    for (size_t i = 0; i < w.size(); ++i) expected[i] = 4 * kSamples * wrong[i] / sum;
    EXPECT_LT(chi2_test(observed, expected).p_value, 1e-3);
}

} // namespace
} // namespace illum
