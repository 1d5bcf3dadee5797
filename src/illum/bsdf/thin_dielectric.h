// A thin dielectric pane (a window): two parallel smooth interfaces so close that the light leaves where
// it entered. Summing the inter-reflections between the faces (a geometric series; pbrt-v4 §9.5.1 and
// the classic slab formula) gives, with single-face Fresnel reflectance R and T = 1 - R,
//   R' = R + T² R / (1 - R²),   T' = 1 - R'
// for reflection in the mirror direction and transmission straight through (wi = -wo, no bending, so no
// 1/η² scaling). Lossless; both lobes are deltas.
#pragma once

#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"

namespace illum {

class ThinDielectricBxDF final : public BxDF {
public:
    explicit ThinDielectricBxDF(float eta, FresnelMode mode = FresnelMode::Exact) : fresnel_{eta, mode} {
        using namespace bsdf_detail;
        ILLUM_REQUIRE(in_range(eta, 1e-3f, 100), "thin-dielectric",
                      "eta must be in (0, 100], got " + str(eta));
    }
    std::uint8_t flags() const override { return kSpecularReflection | kSpecularTransmission; }
    bool isotropic() const override { return true; }
    Bsdf3 f(Vector3f, Vector3f, TransportMode) const override { return {}; }
    SolidAnglePdf pdf(Vector3f, Vector3f, TransportMode) const override { return SolidAnglePdf(0); }

    // Reflectance of the pane for light at |cos θ| (both faces, all inter-reflections).
    float reflectance(float cos_theta) const {
        float R = fresnel_(std::abs(cos_theta)), T = 1 - R;
        if (R < 1) R += T * T * R / (1 - R * R);
        return R;
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f, TransportMode) const override {
        if (wo.z == 0) return std::nullopt;
        float R = reflectance(wo.z), T = 1 - R;
        if (uc < R || T <= 0) {
            Vector3f wi = reflect_z(wo);
            return BSDFSample{wi, Bsdf3(SampledSpectrum(R / std::abs(wi.z))), SolidAnglePdf(R),
                              kSpecularReflection};
        }
        Vector3f wi = -wo;
        return BSDFSample{wi, Bsdf3(SampledSpectrum(T / std::abs(wi.z))), SolidAnglePdf(T),
                          kSpecularTransmission};
    }

private:
    DielectricFresnel fresnel_;
};

} // namespace illum
