// Torrance & Sparrow 1967, "Theory for Off-Specular Reflection From Roughened Surfaces", JOSA 57(9):
// V-groove facets whose normals deviate from the mean normal by an angle θm with a Gaussian
// distribution, D(m) ∝ exp(-θm² / (2σ²)) (their eq. 21 with c² = 1/(2σ²)), the V-groove
// shadowing/masking term G (their eqs. 25-27, in Blinn's closed form, see vcavity_G), the Fresnel
// reflectance of a facet, and the specular term in the form with 1/(4 cos θi cos θo) (the facet-to-
// surface Jacobian of their eq. 14):
//   f = kd/π + ks F(wo·h) D(h) G / (4 cos θo cos θi).
// D is normalised numerically (∫ D cos θm dω = 1) at construction. The Fresnel term is the exact
// conductor/dielectric one with index η + ik (k = 0 for a dielectric such as their polished glass), or
// Schlick. Sampling: half vectors from a Beckmann D·cos proposal with α = √2 σ (the small-angle match of
// the Gaussian), reflected; pdf() is that proposal's density, so estimates are unbiased.
#pragma once

#include "illum/bsdf/glossy_diffuse_sampling.h"
#include "illum/bsdf/vcavity.h"

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"
#include "illum/math/warp.h"

namespace illum {

class TorranceSparrowBxDF final : public BxDF {
public:
    TorranceSparrowBxDF(SampledSpectrum kd, SampledSpectrum ks, float sigma_degrees, Fresnel fresnel)
        : kd_(kd), ks_(ks), fresnel_(fresnel) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(kd, 0, 1), "torrance-sparrow", "kd must be in [0, 1], got " + str(kd));
        ILLUM_REQUIRE(in_range(ks, 0, 1), "torrance-sparrow", "ks must be in [0, 1], got " + str(ks));
        ILLUM_REQUIRE(in_range(kd + ks, 0, 1), "torrance-sparrow",
                      "kd + ks must be <= 1, got " + str(kd + ks));
        ILLUM_REQUIRE(in_range(sigma_degrees, 0.1f, 60), "torrance-sparrow",
                      "sigma must be in [0.1, 60] degrees, got " + str(sigma_degrees));
        SampledSpectrum e = fresnel.eta;
        ILLUM_REQUIRE(all_positive(e), "torrance-sparrow", "eta must be > 0, got " + str(e));
        ILLUM_REQUIRE(in_range(fresnel.k, 0, 1e4f), "torrance-sparrow",
                      "k must be >= 0, got " + str(fresnel.k));
        float sigma = sigma_degrees * kPi / 180;
        inv_two_sigma2_ = 1 / (2 * sigma * sigma);
        // norm = 2π ∫_0^{π/2} exp(-θ²/(2σ²)) cos θ sin θ dθ by composite Simpson (2048 intervals).
        const int n = 2048;
        double h = (kPiD / 2) / n, sum = 0;
        for (int i = 0; i <= n; ++i) {
            double t = i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
            sum += w * std::exp(-t * t * inv_two_sigma2_) * std::cos(t) * std::sin(t);
        }
        inv_norm_ = float(1 / (2 * kPiD * sum * h / 3));
        proposal_ = MicrofacetDistribution(MicrofacetType::Beckmann, std::sqrt(2.0f) * sigma,
                                           std::sqrt(2.0f) * sigma);
        p_spec_ = specular_lobe_probability(kd, ks);
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kGlossyReflection; }

    float D(Vector3f m) const {
        if (m.z <= 0) return 0;
        float t = safe_acos(m.z);
        return std::exp(-t * t * inv_two_sigma2_) * inv_norm_;
    }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        return vcavity_microfacet_f(wo, wi, kd_, ks_, fresnel_, [this](Vector3f h) { return D(h); });
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return sample_glossy_diffuse(*this, proposal_, p_spec_, wo, uc, u, mode);
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        return SolidAnglePdf(glossy_diffuse_pdf(proposal_, p_spec_, wo, wi));
    }

private:
    SampledSpectrum kd_, ks_;
    Fresnel fresnel_;
    float inv_two_sigma2_ = 1, inv_norm_ = 1, p_spec_ = 0;
    MicrofacetDistribution proposal_;
};

} // namespace illum
