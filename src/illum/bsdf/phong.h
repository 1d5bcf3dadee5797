// Energy-normalised (modified) Phong: Lafortune & Willems 1994, "Using the Modified Phong Reflectance
// Model for Physically Based Rendering", eqs. 4-6:
//   f = kd/π + ks (n + 2)/(2π) cos^n α,   α = angle between wi and the mirror direction of wo.
// Reciprocal; with kd + ks <= 1 the albedo is at most 1 (eq. 7). Sampling: pick the diffuse lobe with
// probability mean(kd)/(mean(kd) + mean(ks)) (cosine-weighted), else cos α = u^(1/(n+1)) around the
// mirror direction (pdf (n+1)/(2π) cos^n α); lobe samples below the horizon are rejected.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/microfacet.h"
#include "illum/math/warp.h"

namespace illum {

class PhongBxDF final : public BxDF {
public:
    PhongBxDF(SampledSpectrum kd, SampledSpectrum ks, float exponent) : kd_(kd), ks_(ks), n_(exponent) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(kd, 0, 1), "phong", "kd must be in [0, 1], got " + str(kd));
        ILLUM_REQUIRE(in_range(ks, 0, 1), "phong", "ks must be in [0, 1], got " + str(ks));
        ILLUM_REQUIRE(in_range(kd + ks, 0, 1), "phong",
                      "kd + ks must be <= 1 for energy conservation, got " + str(kd + ks));
        ILLUM_REQUIRE(in_range(exponent, 0, 1e5f), "phong",
                      "exponent must be in [0, 100000], got " + str(exponent));
        p_spec_ = specular_lobe_probability(kd, ks);
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kGlossyReflection; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        float c = std::max(0.0f, dot(wi, reflect_z(wo)));
        return Bsdf3(kd_ * kInvPi + ks_ * ((n_ + 2) * (0.5f * kInvPi) * std::pow(c, n_)));
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        if (wo.z == 0) return std::nullopt;
        Vector3f wi;
        if (uc < p_spec_) {
            float cos_a = std::pow(u.x, 1 / (n_ + 1)), sin_a = safe_sqrt(1 - cos_a * cos_a);
            Vector3f local = spherical_direction(sin_a, cos_a, 2 * kPi * u.y);
            wi = Frame::from_z(reflect_z(wo)).to_world(local);
        } else {
            wi = sample_cosine_hemisphere(u);
            if (wo.z < 0) wi.z = -wi.z;
        }
        if (!same_hemisphere(wo, wi)) return std::nullopt;
        float p = pdf(wo, wi, mode).value;
        if (!(p > 0)) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(p), kGlossyReflection};
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        float c = std::max(0.0f, dot(wi, reflect_z(wo)));
        float ps = (n_ + 1) * (0.5f * kInvPi) * std::pow(c, n_);
        return SolidAnglePdf(p_spec_ * ps + (1 - p_spec_) * std::abs(wi.z) * kInvPi);
    }

private:
    SampledSpectrum kd_, ks_;
    float n_, p_spec_;
};

} // namespace illum
