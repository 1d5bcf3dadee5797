// Cook & Torrance 1982, "A Reflectance Model for Computer Graphics", ACM TOG 1(1): a diffuse and a
// specular term, R = d Rd + s Rs, with the Beckmann distribution (their eq. 7, α = m the rms slope),
// the V-cavity geometric attenuation G (eq. 6), and the Fresnel reflectance at the angle between the
// view and the half vector (eq. 8, exact here, for η + ik; or Schlick):
//   f = kd/π + ks F(wo·h) D(h) G / (4 cos θo cos θi).
// The paper writes Rs = F D G / (π (n·l)(n·v)) with D unnormalised (no 1/π); with the normalised D
// used here (∫ D cos θh dω = 1) the reflection-geometry Jacobian gives the 1/4 of Walter et al. 2007,
// which makes the specular albedo at most F. Sampling: Beckmann D cos θh half vectors, reflected.
#pragma once

#include "illum/bsdf/glossy_diffuse_sampling.h"
#include "illum/bsdf/vcavity.h"

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"
#include "illum/math/warp.h"

namespace illum {

class CookTorranceBxDF final : public BxDF {
public:
    CookTorranceBxDF(SampledSpectrum kd, SampledSpectrum ks, float m, Fresnel fresnel)
        : kd_(kd), ks_(ks), fresnel_(fresnel), distrib_(MicrofacetType::Beckmann, m, m) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(kd, 0, 1), "cook-torrance", "kd must be in [0, 1], got " + str(kd));
        ILLUM_REQUIRE(in_range(ks, 0, 1), "cook-torrance", "ks must be in [0, 1], got " + str(ks));
        ILLUM_REQUIRE(in_range(kd + ks, 0, 1), "cook-torrance", "kd + ks must be <= 1, got " + str(kd + ks));
        ILLUM_REQUIRE(in_range(m, 1e-3f, 1), "cook-torrance",
                      "roughness m must be in [0.001, 1], got " + str(m));
        SampledSpectrum e = fresnel.eta;
        ILLUM_REQUIRE(all_positive(e), "cook-torrance", "eta must be > 0, got " + str(e));
        ILLUM_REQUIRE(in_range(fresnel.k, 0, 1e4f), "cook-torrance", "k must be >= 0, got " + str(fresnel.k));
        p_spec_ = specular_lobe_probability(kd, ks);
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kGlossyReflection; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        return vcavity_microfacet_f(wo, wi, kd_, ks_, fresnel_, [this](Vector3f h) { return distrib_.D(h); });
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return sample_glossy_diffuse(*this, distrib_, p_spec_, wo, uc, u, mode);
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        return SolidAnglePdf(glossy_diffuse_pdf(distrib_, p_spec_, wo, wi));
    }

private:
    SampledSpectrum kd_, ks_;
    Fresnel fresnel_;
    MicrofacetDistribution distrib_;
    float p_spec_ = 0;
};

} // namespace illum
