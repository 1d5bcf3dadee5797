// Blinn-Phong (Blinn 1977, "Models of Light Reflection for Computer Synthesized Pictures") with the
// normalisation of Ashikhmin & Shirley 2000 ("An Anisotropic Phong BRDF Model", eq. 4 without Fresnel):
//   f = kd/π + ks (n + 1)/(8π) cos^n θh / (|wi·h| max(|cos θi|, |cos θo|)).
// Sampling the half vector with pdf (n+1)/(2π) cos^n θh and reflecting (pdf_h / (4 |wo·h|)) gives the
// specular lobe the weight ks |cos θi| / max(|cos θi|, |cos θo|) <= ks, so with kd + ks <= 1 the albedo is
// at most 1. Reciprocal.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/glossy_diffuse_sampling.h"
#include "illum/bsdf/microfacet.h"
#include "illum/math/warp.h"

namespace illum {

class BlinnPhongBxDF final : public BxDF {
public:
    BlinnPhongBxDF(SampledSpectrum kd, SampledSpectrum ks, float exponent) : kd_(kd), ks_(ks), n_(exponent) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(kd, 0, 1), "blinn-phong", "kd must be in [0, 1], got " + str(kd));
        ILLUM_REQUIRE(in_range(ks, 0, 1), "blinn-phong", "ks must be in [0, 1], got " + str(ks));
        ILLUM_REQUIRE(in_range(kd + ks, 0, 1), "blinn-phong",
                      "kd + ks must be <= 1 for energy conservation, got " + str(kd + ks));
        ILLUM_REQUIRE(in_range(exponent, 0, 1e5f), "blinn-phong",
                      "exponent must be in [0, 100000], got " + str(exponent));
        p_spec_ = specular_lobe_probability(kd, ks);
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kGlossyReflection; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        Vector3f h = wo + wi;
        if (length_squared(h) == 0) return Bsdf3(kd_ * kInvPi);
        h = normalize(h);
        float ih = abs_dot(wi, h), m = std::max(std::abs(wi.z), std::abs(wo.z));
        float spec = ih > 0 ? (n_ + 1) / (8 * kPi) * std::pow(std::abs(h.z), n_) / (ih * m) : 0.0f;
        return Bsdf3(kd_ * kInvPi + ks_ * spec);
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return sample_glossy_diffuse(*this, HalfVectorLobe{n_}, p_spec_, wo, uc, u, mode);
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        return SolidAnglePdf(glossy_diffuse_pdf(HalfVectorLobe{n_}, p_spec_, wo, wi));
    }

    // The half-vector lobe p_h(h) = (n + 1)/(2π) cos^n θh, sampled by cos θh = u^(1/(n+1)).
    struct HalfVectorLobe {
        float n;
        Vector3f sample_wm(Vector3f, Point2f u) const {
            float c = std::pow(u.x, 1 / (n + 1)), s = safe_sqrt(1 - c * c);
            return spherical_direction(s, c, 2 * kPi * u.y);
        }
        float pdf_wm(Vector3f, Vector3f h) const { return (n + 1) / (2 * kPi) * std::pow(std::abs(h.z), n); }
    };

private:
    SampledSpectrum kd_, ks_;
    float n_, p_spec_;
};

} // namespace illum
