// The hair BSDF (Chiang et al. 2016, as pbrt-v4): white furnace over a grid of roughnesses, sampling weights
// and chi-square tests, sample() against f() and pdf(), and the absorption helpers.
#include <gtest/gtest.h>

#include <random>

#include "illum/analysis/audit.h"
#include "illum/analysis/stats.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/hair.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

const float kBetas[] = {0.1f, 0.3f, 0.5f, 0.8f, 1.0f};

// With no absorption every bit of light leaves the fibre: ∫ f |cos θi| dωi = ∫ S dωi = 1 for any wo and h
// (Σ A_p = 1 when T = 1, and each M_p N_p is a density over the sphere). Estimated with wi uniform on the
// sphere and h uniform across the fibre; the tolerance is 4.5 standard errors of that estimate plus the
// 0.2% that M_p's low-roughness form and float rounding may cost.
TEST(Hair, WhiteFurnaceHoldsForEveryRoughness) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<float> U(0, 0x1.fffffep-1f);
    const int n = 1 << 18;
    for (float bm : kBetas)
        for (float bn : kBetas) {
            Vector3f wo = sample_uniform_sphere({U(rng), U(rng)});
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; ++i) {
                float h = -1 + 2 * U(rng);
                HairBxDF hair(h, 1.55f, SampledSpectrum(0.0f), bm, bn, 2);
                Vector3f wi = sample_uniform_sphere({U(rng), U(rng)});
                double y = hair.f(wo, wi, TransportMode::Radiance)[1] * std::abs(wi.z) / uniform_sphere_pdf();
                sum += y;
                sum2 += y * y;
            }
            double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
            EXPECT_NEAR(mean, 1.0, 4.5 * se + 2e-3)
                << "beta_m " << bm << " beta_n " << bn << " (se " << se << ")";
        }
}

// The same integral by a midpoint rule over (sin θi, φi) around the fibre, fine enough for the narrowest
// lobe (β_m = 0.1's TT lobe is 0.04 rad wide, β_n = 0.1's logistic 0.024 rad): 1 within 10⁻³.
TEST(Hair, WhiteFurnaceByQuadrature) {
    struct Case {
        float bm, bn, h;
        Vector3f wo;
    };
    const Case cases[] = {{0.1f, 0.1f, 0.3f, normalize(Vector3f(0.3f, 0.5f, 0.8f))},
                          {0.3f, 0.3f, -0.9f, normalize(Vector3f(-0.8f, 0.1f, 0.5f))},
                          {0.5f, 1.0f, 0.0f, normalize(Vector3f(0.0f, -0.6f, 0.8f))},
                          {1.0f, 0.1f, 0.7f, normalize(Vector3f(0.6f, 0.6f, -0.5f))}};
    const int n = 1500;
    for (const Case& c : cases) {
        HairBxDF hair(c.h, 1.55f, SampledSpectrum(0.0f), c.bm, c.bn, 2);
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            double x = -1 + (i + 0.5) * 2.0 / n, r = std::sqrt(1 - x * x);
            for (int j = 0; j < n; ++j) {
                double phi = (j + 0.5) * 2 * kPiD / n;
                Vector3f wi(float(x), float(r * std::cos(phi)), float(r * std::sin(phi)));
                sum += hair.f(c.wo, wi, TransportMode::Radiance)[1] * std::abs(wi.z);
            }
        }
        EXPECT_NEAR(sum * (2.0 / n) * (2 * kPiD / n), 1.0, 1e-3) << "beta " << c.bm << "/" << c.bn;
    }
}

// Without absorption A_p's shares are the sampling probabilities, so every sample's weight f |cos| / pdf
// is 1 (pbrt-v4's SamplingWeights test); and sample() returns what f() and pdf() say at its direction.
TEST(Hair, SampleWeightIsOneWithoutAbsorptionAndMatchesFAndPdf) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<float> U(0, 0x1.fffffep-1f);
    for (float bm : kBetas)
        for (float bn : kBetas) {
            for (int i = 0; i < 2000; ++i) {
                float h = -1 + 2 * U(rng);
                HairBxDF lossless(h, 1.55f, SampledSpectrum(0.0f), bm, bn, 2);
                HairBxDF brown(h, 1.55f, SampledSpectrum(Color3(0.54f, 0.9f, 1.78f)), bm, bn, 2);
                Vector3f wo = sample_uniform_sphere({U(rng), U(rng)});
                float uc = U(rng);
                Point2f u(U(rng), U(rng));
                if (auto s = lossless.sample(wo, uc, u, TransportMode::Radiance)) {
                    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight()[c], 1.0f, 2e-3f) << bm << " " << bn;
                }
                if (auto s = brown.sample(wo, uc, u, TransportMode::Radiance)) {
                    Bsdf3 f = brown.f(wo, s->wi, TransportMode::Radiance);
                    float p = brown.pdf(wo, s->wi, TransportMode::Radiance).value;
                    EXPECT_NEAR(s->pdf.value, p, 1e-5f * p);
                    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], 1e-5f * f[c]);
                    EXPECT_EQ(s->is_reflection(), same_hemisphere(wo, s->wi));
                }
            }
        }
}

// sample() against pdf(): the audit's chi-square test (36 x 72 bins over the sphere) for a spread of
// roughnesses, offsets h and tilts, at 1% family-wise significance.
TEST(Hair, SamplingPassesChiSquare) {
    struct Case {
        float h, bm, bn, alpha;
    };
    const Case cases[] = {{0.0f, 0.3f, 0.3f, 2},
                          {0.6f, 0.2f, 0.6f, 2},
                          {-0.9f, 0.6f, 0.2f, 0},
                          {0.3f, 1.0f, 1.0f, 5},
                          {-0.4f, 0.15f, 0.9f, -3}};
    const Vector3f wos[] = {direction_deg(20, 35), direction_deg(70, 200), direction_deg(120, 10)};
    double alpha = sidak_significance(0.01, int(std::size(cases) * std::size(wos)));
    std::uint64_t seed = 1;
    for (const Case& c : cases) {
        HairBxDF hair(c.h, 1.55f, SampledSpectrum(Color3(0.3f, 0.6f, 1.2f)), c.bm, c.bn, c.alpha);
        for (Vector3f wo : wos) {
            ChiSquareResult r = chi_square_test(hair, wo, TransportMode::Radiance, 100000, 36, 72, ++seed);
            EXPECT_FALSE(r.zero_pdf_hit) << r.detail;
            EXPECT_GT(r.p_value, alpha) << "h " << c.h << " beta " << c.bm << "/" << c.bn << ": " << r.detail;
        }
    }
}

// Chiang et al. 2016 §5.1's pigment absorptions; and eq. 10 inverted: a colour of 1 absorbs nothing, a
// darker one more.
TEST(Hair, AbsorptionFromPigmentsAndColour) {
    Color3 s = HairBxDF::sigma_a_from_concentration(1.3f, 0.5f);
    EXPECT_NEAR(s.r, 1.3f * 0.419f + 0.5f * 0.187f, 1e-6f);
    EXPECT_NEAR(s.g, 1.3f * 0.697f + 0.5f * 0.4f, 1e-6f);
    EXPECT_NEAR(s.b, 1.3f * 1.37f + 0.5f * 1.05f, 1e-6f);
    SampledSpectrum white = HairBxDF::sigma_a_from_reflectance(SampledSpectrum(1.0f), 0.3f);
    EXPECT_EQ(white[0], 0.0f);
    SampledSpectrum c = HairBxDF::sigma_a_from_reflectance(SampledSpectrum(Color3(0.8f, 0.4f, 0.1f)), 0.3f);
    EXPECT_LT(c[0], c[1]);
    EXPECT_LT(c[1], c[2]);
    // Eq. 10 at β_n = 0.3: the denominator 5.969 - 0.215·0.3 + 2.532·0.09 - 10.73·0.027 + 5.574·0.0081 +
    // 0.245·0.00243.
    double d = 5.969 - 0.215 * 0.3 + 2.532 * 0.09 - 10.73 * 0.027 + 5.574 * 0.0081 + 0.245 * 0.00243;
    EXPECT_NEAR(c[1], std::pow(std::log(0.4) / d, 2), 1e-5);
}

TEST(Hair, RejectsParametersOutOfRange) {
    EXPECT_THROW(HairBxDF(1.5f, 1.55f, SampledSpectrum(0.0f), 0.3f, 0.3f, 2), Error);
    EXPECT_THROW(HairBxDF(0, 1.55f, SampledSpectrum(0.0f), 1.3f, 0.3f, 2), Error);
    EXPECT_THROW(HairBxDF(0, 1.55f, SampledSpectrum(-1.0f), 0.3f, 0.3f, 2), Error);
}

} // namespace
} // namespace illum
