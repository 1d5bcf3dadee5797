// A smooth dielectric interface (glass, water): specular reflection and refraction. The outside is +z
// (index 1), the inside -z (index η). Fresnel reflectance R (exact unpolarised or Schlick) picks
// reflection with probability R and refraction with probability T = 1 - R; total internal reflection
// reflects everything. Refracted radiance is scaled by 1/η'² in radiance transport mode (η' = n_t/n_i;
// Veach 1997, thesis §5.2), not in importance mode. Both lobes are deltas.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/microfacet.h"

namespace illum {

class DielectricBxDF final : public BxDF {
public:
    explicit DielectricBxDF(float eta, FresnelMode mode = FresnelMode::Exact) : fresnel_{eta, mode} {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(eta, 1e-3f, 100), "dielectric", "eta must be in (0, 100], got " + str(eta));
    }
    std::uint8_t flags() const override {
        return fresnel_.eta == 1 ? kSpecularTransmission : (kSpecularReflection | kSpecularTransmission);
    }
    bool isotropic() const override { return true; }
    Bsdf3 f(Vector3f, Vector3f, TransportMode) const override { return {}; }
    SolidAnglePdf pdf(Vector3f, Vector3f, TransportMode) const override { return SolidAnglePdf(0); }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return sample_lobes(wo, uc, u, mode, Lobes::All);
    }
    // Reflection with probability pr / (pr + pt), pr = R and pt = T unless a side is excluded.
    std::optional<BSDFSample> sample_lobes(Vector3f wo, float uc, Point2f, TransportMode mode,
                                           Lobes lobes) const {
        float R = fresnel_(wo.z), T = 1 - R;
        float pr = lobes == Lobes::Transmission ? 0 : R, pt = lobes == Lobes::Reflection ? 0 : T;
        if (!(pr + pt > 0)) return std::nullopt;
        if (uc < pr / (pr + pt)) {
            Vector3f wi = reflect_z(wo);
            if (wi.z == 0) return std::nullopt;
            return BSDFSample{wi, Bsdf3(SampledSpectrum(R / std::abs(wi.z))), SolidAnglePdf(pr / (pr + pt)),
                              kSpecularReflection};
        }
        Vector3f wi;
        float etap;
        if (!refract(wo, Vector3f(0, 0, 1), fresnel_.eta, &etap, &wi) || wi.z == 0) return std::nullopt;
        float ft = T / std::abs(wi.z);
        if (mode == TransportMode::Radiance) ft /= etap * etap;
        BSDFSample s{wi, Bsdf3(SampledSpectrum(ft)), SolidAnglePdf(pt / (pr + pt)), kSpecularTransmission};
        s.eta = etap;
        return s;
    }
    SolidAnglePdf pdf_lobes(Vector3f, Vector3f, TransportMode, Lobes) const { return SolidAnglePdf(0); }
    float eta() const { return fresnel_.eta; }
    const DielectricFresnel& fresnel() const { return fresnel_; }

private:
    DielectricFresnel fresnel_;
};

} // namespace illum
