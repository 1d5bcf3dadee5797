// Lambertian (ideal diffuse) reflection: f = ρ/π, reciprocal, albedo ρ at every angle.
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/math/warp.h"

namespace illum {

class LambertBxDF final : public BxDF {
public:
    explicit LambertBxDF(SampledSpectrum reflectance) : reflectance_(reflectance) {}

    std::uint8_t flags() const override { return reflectance_.is_black() ? kNone : kDiffuseReflection; }
    bool isotropic() const override { return true; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {};
        return Bsdf3(reflectance_ * kInvPi);
    }

    bool reads_lobe_sample() const override { return false; }

    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f u, TransportMode) const override {
        Vector3f wi = sample_cosine_hemisphere(u);
        if (wo.z < 0) wi.z = -wi.z;
        float pdf = cosine_hemisphere_pdf(std::abs(wi.z));
        if (!(pdf > 0)) return std::nullopt;
        return BSDFSample{wi, Bsdf3(reflectance_ * kInvPi), SolidAnglePdf(pdf), kDiffuseReflection};
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return SolidAnglePdf(0);
        return SolidAnglePdf(cosine_hemisphere_pdf(std::abs(wi.z)));
    }

    BSDFEval eval(Vector3f wo, Vector3f wi, TransportMode) const override {
        if (!same_hemisphere(wo, wi)) return {{}, 0, 0, true};
        return {Bsdf3(reflectance_ * kInvPi), cosine_hemisphere_pdf(std::abs(wi.z)),
                cosine_hemisphere_pdf(std::abs(wo.z)), true};
    }

    SampledSpectrum reflectance() const { return reflectance_; }

private:
    SampledSpectrum reflectance_;
};

} // namespace illum
