// The wavelengths a spectral path carries: their density, its normalisation, and dispersion's termination.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "illum/radiometry/color_space.h"
#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {
namespace {

// The tabulated sampler's density integrates to 1 over [360, 830] nm and stays within 0.3% of pbrt-v4's
// analytic density (the bins are ~1.8 nm wide, over which the analytic density changes < 0.3%).
TEST(SampledWavelengths, TabulatedDensityIsNormalisedAndCloseToTheAnalyticOne) {
    const VisibleWavelengthTable& t = visible_wavelength_table();
    EXPECT_FLOAT_EQ(t.lambda[0], kVisibleMin);
    EXPECT_NEAR(t.lambda[kVisibleBins], kVisibleMax, 0.5);
    double integral = 0, worst = 0;
    for (int i = 0; i < kVisibleBins; ++i) {
        double w = t.lambda[i + 1] - t.lambda[i];
        ASSERT_GT(w, 0);
        integral += t.pdf[i] * w;
        float mid = 0.5f * (t.lambda[i] + t.lambda[i + 1]);
        worst = std::max(worst, std::abs(double(t.pdf[i]) / visible_wavelength_pdf(mid) - 1));
    }
    EXPECT_NEAR(integral, 1, 1e-5);
    EXPECT_LT(worst, 3e-3);
    std::printf("largest relative difference from the analytic density: %.2e\n", worst);
}

// A sample's density is the density of the bin it falls in: histogram 10^6 samples into the bins and
// compare the counts with pdf · width · N (binomial σ).
TEST(SampledWavelengths, SamplesFollowTheirDensity) {
    const VisibleWavelengthTable& t = visible_wavelength_table();
    const int n = 1000000, bins = 47; // 10 nm bins
    std::vector<double> count(bins, 0.0), expected(bins, 0.0);
    for (int k = 0; k < n; ++k) {
        float pdf;
        float l = sample_visible_tabulated((k + 0.5f) / n, &pdf);
        ASSERT_GE(l, kVisibleMin);
        ASSERT_LE(l, kVisibleMax);
        count[std::min(bins - 1, int((l - kVisibleMin) / 10))] += 1;
    }
    for (int i = 0; i < kVisibleBins; ++i)
        for (float l = t.lambda[i]; l < t.lambda[i + 1]; l += 0.01f)
            expected[std::min(bins - 1, int((l - kVisibleMin) / 10))] += t.pdf[i] * 0.01 * n;
    for (int b = 0; b < bins; ++b)
        EXPECT_NEAR(count[b], expected[b], 5 * std::sqrt(expected[b]) + 0.01 * expected[b] + 2) << b;
}

TEST(SampledWavelengths, FourWavelengthsAtEqualOffsetsAndDispersionKeepsTheHero) {
    const RGBColorSpace* cs = &RGBColorSpace::srgb();
    SampledWavelengths w = SampledWavelengths::sample_visible(0.1f, cs);
    float p0 = w.pdf[0];
    for (int i = 0; i < kSpectrumSamples; ++i) {
        float pdf;
        EXPECT_FLOAT_EQ(w.lambda[i], sample_visible_tabulated(std::fmod(0.1f + i / 4.0f, 1.0f), &pdf));
        EXPECT_FLOAT_EQ(w.pdf[i], pdf);
    }
    w.terminate_secondary();
    EXPECT_TRUE(w.secondary_terminated());
    EXPECT_FLOAT_EQ(w.pdf[0], p0 / 4);
    for (int i = 1; i < kSpectrumSamples; ++i) EXPECT_EQ(w.pdf[i], 0);
    w.terminate_secondary(); // idempotent
    EXPECT_FLOAT_EQ(w.pdf[0], p0 / 4);
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    rgb.terminate_secondary(); // nothing to terminate in RGB mode
    EXPECT_FALSE(rgb.secondary_terminated());
}

} // namespace
} // namespace illum
