// The chi-square machinery: the incomplete gamma function against known values, acceptance of a
// correct sampler, and rejection of deliberately mis-weighted pdfs.
#include <gtest/gtest.h>

#include "illum/analysis/audit.h"
#include "illum/analysis/stats.h"
#include "illum/analysis/weighted_histogram_test.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/coated.h"
#include "illum/bsdf/lambert.h"
#include "illum/bsdf/phong.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

TEST(Stats, ChiSquareSurvivalMatchesTables) {
    // Critical values of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
    EXPECT_NEAR(chi_square_survival(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_survival(6.635, 1), 0.01, 1e-4);
    EXPECT_NEAR(chi_square_survival(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_survival(124.342, 100), 0.05, 1e-4);
    EXPECT_NEAR(chi_square_survival(2, 2), std::exp(-1.0), 1e-12); // Q(1, x) = e^-x
    EXPECT_NEAR(regularized_gamma_p(0.5, 1.0), std::erf(1.0), 1e-12);
    EXPECT_NEAR(regularized_gamma_p(3, 2) + regularized_gamma_q(3, 2), 1, 1e-14);
    EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
    EXPECT_NEAR(sidak_significance(0.01, 100), 1.00503e-4, 1e-8);
}

// Lambert sampled cosine-weighted but claiming another density.
class MisweightedLambert final : public BxDF {
public:
    explicit MisweightedLambert(int kind) : kind_(kind) {}
    std::uint8_t flags() const override { return kDiffuseReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode m) const override { return base_.f(wo, wi, m); }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode m) const override {
        auto s = base_.sample(wo, uc, u, m);
        if (s) s->pdf = pdf(wo, s->wi, m);
        return s;
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        float c = std::abs(wi.z);
        if (kind_ == 0) return SolidAnglePdf(uniform_hemisphere_pdf()); // grossly wrong
        // Subtly wrong: cos^1.1 normalised, (n+1)/(2π) cos^n with n = 1.1.
        return SolidAnglePdf(2.1f / (2 * kPi) * std::pow(c, 1.1f));
    }

private:
    LambertBxDF base_{SampledSpectrum(0.5f)};
    int kind_;
};

TEST(ChiSquare, AcceptsACorrectSampler) {
    LambertBxDF lambert(SampledSpectrum(0.5f));
    PhongBxDF phong(SampledSpectrum(0.3f), SampledSpectrum(0.6f), 30);
    for (double t : {0.0, 45.0, 85.0}) {
        auto r = chi_square_test(lambert, direction_deg(t, 20), TransportMode::Radiance, 100000, 36, 72, 5);
        EXPECT_GT(r.p_value, 0.001) << r.detail;
        r = chi_square_test(phong, direction_deg(t, 20), TransportMode::Radiance, 100000, 36, 72, 6);
        EXPECT_GT(r.p_value, 0.001) << r.detail;
    }
}

TEST(ChiSquare, RejectsMisweightedPdfs) {
    for (int kind : {0, 1}) {
        MisweightedLambert bad(kind);
        auto r = chi_square_test(bad, direction_deg(30, 0), TransportMode::Radiance, 100000, 36, 72, 5);
        EXPECT_LT(r.p_value, 1e-4) << "kind " << kind << ": " << r.detail;
        // And the audit reports it as a failure.
        AuditOptions o;
        o.chi2_samples = 50000;
        o.energy_samples = 5000;
        o.pairs = 100;
        auto a = audit_bxdf(bad, AuditTraits{}, o);
        EXPECT_FALSE(a.passed());
    }
}

// A stochastic-looking Lambert: f() exact, sample() weights tilted by (1 + tilt wi.x), which moves
// energy from -x to +x without changing the albedo much (what a wrong Jacobian in a random walk does).
class TiltedLambert final : public BxDF {
public:
    explicit TiltedLambert(float tilt) : tilt_(tilt) {}
    std::uint8_t flags() const override { return kDiffuseReflection; }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode m) const override { return base_.f(wo, wi, m); }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode m) const override {
        auto s = base_.sample(wo, uc, u, m);
        if (s) {
            s->f = Bsdf3(s->f.s * (1 + tilt_ * s->wi.x));
            s->pdf_is_proportional = true;
        }
        return s;
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode m) const override {
        return base_.pdf(wo, wi, m);
    }

private:
    LambertBxDF base_{SampledSpectrum(0.5f)};
    float tilt_;
};

TEST(WeightedHistogram, AcceptsConsistentSamplingAndRejectsATilt) {
    // Calibration: a correct deterministic model and a correct stochastic one pass at the audit's settings.
    AuditOptions o;
    for (double t : {10.0, 60.0}) {
        auto r = weighted_histogram_test(TiltedLambert(0), direction_deg(t, 20), TransportMode::Radiance,
                                         o.weighted_samples, o.weighted_cos_bins, o.weighted_phi_bins,
                                         o.weighted_f_per_bin, 11);
        EXPECT_GT(r.p_value, 1e-3) << r.detail;
    }
    CoatedDiffuseBxDF coated(DielectricInterface(1.5f, {0.2f, 0.2f}), LambertBxDF(SampledSpectrum(0.7f)),
                             LayerMedium{}, 10, 1);
    auto r =
        weighted_histogram_test(coated, direction_deg(40, 20), TransportMode::Radiance, o.weighted_samples,
                                o.weighted_cos_bins, o.weighted_phi_bins, o.weighted_f_per_bin, 12);
    EXPECT_GT(r.p_value, 1e-3) << r.detail;
    // A 10% tilt of the sample weights is found.
    r = weighted_histogram_test(TiltedLambert(0.1f), direction_deg(30, 20), TransportMode::Radiance,
                                o.weighted_samples, o.weighted_cos_bins, o.weighted_phi_bins,
                                o.weighted_f_per_bin, 13);
    EXPECT_LT(r.p_value, 1e-6) << r.detail;
    // And the audit of a stochastic model reports it.
    AuditTraits traits;
    traits.stochastic = true;
    o.energy_samples = 5000;
    o.pairs = 100;
    EXPECT_FALSE(audit_bxdf(TiltedLambert(0.1f), traits, o).passed());
    EXPECT_TRUE(audit_bxdf(TiltedLambert(0.0f), traits, o).passed());
}

} // namespace
} // namespace illum
