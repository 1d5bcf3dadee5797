// Diffuse transmission for thin translucent sheets (paper, leaves, lamp shades): Lambertian reflection
// R/π on the side of wo and Lambertian transmission T/π to the other side (pbrt-v4 §9.3 describes the
// same model). The sheet is thin, so there is no refraction and no η scaling; reciprocal both ways.
// R + T <= 1; lossless when R + T = 1. Sampling picks a side with probability proportional to mean R
// and mean T, then a cosine-weighted direction.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/math/warp.h"

namespace illum {

class DiffuseTransmissionBxDF final : public BxDF {
public:
    DiffuseTransmissionBxDF(SampledSpectrum reflectance, SampledSpectrum transmittance)
        : r_(reflectance), t_(transmittance) {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(r_, 0, 1), "diffuse-transmission",
                      "reflectance must be in [0, 1], got " + str(r_));
        ILLUM_REQUIRE(in_range(t_, 0, 1), "diffuse-transmission",
                      "transmittance must be in [0, 1], got " + str(t_));
        ILLUM_REQUIRE(in_range(r_ + t_, 0, 1), "diffuse-transmission",
                      "reflectance + transmittance must be <= 1, got " + str(r_ + t_));
        float r = r_.average(), t = t_.average();
        p_r_ = r + t > 0 ? r / (r + t) : 0.5f;
    }
    std::uint8_t flags() const override { return kDiffuseReflection | kDiffuseTransmission; }
    bool isotropic() const override { return true; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (wo.z == 0 || wi.z == 0) return {};
        return Bsdf3((same_hemisphere(wo, wi) ? r_ : t_) * kInvPi);
    }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        if (wo.z == 0) return std::nullopt;
        Vector3f wi = sample_cosine_hemisphere(u);
        bool reflect = uc < p_r_;
        if ((wo.z < 0) == reflect) wi.z = -wi.z;
        float p = pdf(wo, wi, mode).value;
        if (!(p > 0)) return std::nullopt;
        return BSDFSample{wi, f(wo, wi, mode), SolidAnglePdf(p),
                          reflect ? kDiffuseReflection : kDiffuseTransmission};
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (wo.z == 0 || wi.z == 0) return SolidAnglePdf(0);
        float p = same_hemisphere(wo, wi) ? p_r_ : 1 - p_r_;
        return SolidAnglePdf(p * std::abs(wi.z) * kInvPi);
    }

private:
    SampledSpectrum r_, t_;
    float p_r_ = 0.5f;
};

} // namespace illum
