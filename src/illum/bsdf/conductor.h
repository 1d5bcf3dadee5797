// A smooth conductor: specular reflection weighted by the exact conductor Fresnel equations with complex
// index η + ik (or Schlick's approximation with F0 from η, k). Delta lobe, as the mirror.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"

namespace illum {

// Gold's complex index of refraction at the centres of the R, G, B bands (~650, 550, 450 nm; Johnson &
// Christy 1972 as tabulated by refractiveindex.info, averaged over each band).
inline constexpr Color3 kGoldEta{0.143119f, 0.374957f, 1.442480f};
inline constexpr Color3 kGoldK{3.983160f, 2.385721f, 1.603215f};

class ConductorBxDF final : public BxDF {
public:
    ConductorBxDF(SampledSpectrum eta, SampledSpectrum k, FresnelMode mode = FresnelMode::Exact)
        : fresnel_{eta, k, mode} {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(all_positive(eta), "conductor", "eta must be > 0, got " + str(eta));
        ILLUM_REQUIRE(in_range(k, 0, 1e4f), "conductor", "k must be >= 0, got " + str(k));
    }
    std::uint8_t flags() const override { return kSpecularReflection; }
    bool isotropic() const override { return true; }
    Bsdf3 f(Vector3f, Vector3f, TransportMode) const override { return {}; }
    SolidAnglePdf pdf(Vector3f, Vector3f, TransportMode) const override { return SolidAnglePdf(0); }
    bool reads_lobe_sample() const override { return false; }
    std::optional<BSDFSample> sample(Vector3f wo, float, Point2f, TransportMode) const override {
        Vector3f wi = reflect_z(wo);
        if (wi.z == 0) return std::nullopt;
        SampledSpectrum F = fresnel_(std::abs(wo.z));
        return BSDFSample{wi, Bsdf3(F / std::abs(wi.z)), SolidAnglePdf(1), kSpecularReflection};
    }
    const Fresnel& fresnel() const { return fresnel_; }

private:
    Fresnel fresnel_;
};

} // namespace illum
