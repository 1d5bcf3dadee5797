// Oren-Nayar rough diffuse reflection: V-cavities with a Gaussian distribution of facet slopes of
// standard deviation σ, each facet Lambertian. This is the "qualitative model" of Oren & Nayar 1994,
// "Generalization of Lambert's Reflectance Model", SIGGRAPH, eq. 30 (it drops the interreflection term):
//   f = ρ/π (A + B max(0, cos(φi - φo)) sin α tan β),  α = max(θi, θo), β = min(θi, θo),
//   A = 1 - σ² / (2 (σ² + 0.33)),  B = 0.45 σ² / (σ² + 0.09)   (σ in radians).
// σ = 0 is Lambert. Reciprocal; its albedo is below ρ. Sampled cosine-weighted.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/math/warp.h"

namespace illum {

class OrenNayarBxDF final : public BxDF {
public:
    // sigma_degrees: standard deviation of the facet slope angle, in degrees, [0, 90].
    OrenNayarBxDF(SampledSpectrum reflectance, float sigma_degrees) : reflectance_(reflectance) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(reflectance, 0, 1), "oren-nayar",
                      "reflectance must be in [0, 1], got " + str(reflectance));
        ILLUM_REQUIRE(in_range(sigma_degrees, 0, 90), "oren-nayar",
                      "sigma must be in [0, 90] degrees, got " + str(sigma_degrees));
        float s2 = sqr(sigma_degrees * kPi / 180);
        a_ = 1 - s2 / (2 * (s2 + 0.33f));
        b_ = 0.45f * s2 / (s2 + 0.09f);
    }

    std::uint8_t flags() const override { return reflectance_.is_black() ? kNone : kDiffuseReflection; }
    bool isotropic() const override { return true; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        float sin_i = sin_theta(wi), sin_o = sin_theta(wo);
        float max_cos = 0;
        if (sin_i > 1e-4f && sin_o > 1e-4f)
            max_cos = std::max(0.0f, (wi.x * wo.x + wi.y * wo.y) / (sin_i * sin_o));
        // sin α tan β with α = max(θi, θo): the larger angle has the smaller |cos|.
        float cos_i = abs_cos_theta(wi), cos_o = abs_cos_theta(wo);
        float sin_alpha, tan_beta;
        if (cos_i > cos_o) {
            sin_alpha = sin_o;
            tan_beta = sin_i / cos_i;
        } else {
            sin_alpha = sin_i;
            tan_beta = sin_o / cos_o;
        }
        return Bsdf3(reflectance_ * (kInvPi * (a_ + b_ * max_cos * sin_alpha * tan_beta)));
    }

    bool reads_lobe_sample() const override { return false; }

    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f u, TransportMode mode) const override {
        Vector3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        float pdf = cosine_hemisphere_pdf(std::abs(wi.z));
        if (!(pdf > 0)) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(pdf), kDiffuseReflection};
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        return SolidAnglePdf(cosine_hemisphere_pdf(std::abs(wi.z)));
    }

private:
    SampledSpectrum reflectance_;
    float a_ = 1, b_ = 0;
};

} // namespace illum
