// The two interfaces of a coated (layered) model, each smooth or rough as pbrt-v4's materials choose
// (effectively smooth when both roughness α are below 1e-3): the coat is a dielectric, the base a
// conductor (or any reflection-only BxDF, used directly).
#pragma once

#include <algorithm>

#include "illum/bsdf/conductor.h"
#include "illum/bsdf/dielectric.h"
#include "illum/bsdf/rough_conductor.h"
#include "illum/bsdf/rough_dielectric.h"

namespace illum {

namespace bsdf_detail {
inline MicrofacetDistribution ggx_clamped(Vector2f a) {
    return MicrofacetDistribution(MicrofacetType::GGX, std::clamp(a.x, 1e-3f, 2.0f),
                                  std::clamp(a.y, 1e-3f, 2.0f));
}
} // namespace bsdf_detail

// A dielectric coat: the smooth interface (delta lobes) or a rough one, with restricted sampling.
class DielectricInterface {
public:
    // Smooth when both α are below 1e-3 (pbrt-v4's rule); otherwise α is clamped to [1e-3, 2].
    DielectricInterface(float eta, Vector2f alpha)
        : smooth_(std::max(alpha.x, alpha.y) < 1e-3f), flat_(eta),
          rough_(bsdf_detail::ggx_clamped(alpha), eta) {}
    bool is_specular() const { return smooth_; }
    float eta() const { return flat_.eta(); }
    // The smooth interface's Fresnel reflectance at cos θ (outside for cos θ > 0).
    float fresnel_reflectance(float cos_theta) const { return flat_.fresnel()(cos_theta); }
    std::uint8_t flags() const { return smooth_ ? flat_.flags() : rough_.flags(); }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const {
        return smooth_ ? Bsdf3() : rough_.f(wo, wi, mode);
    }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode,
                                     Lobes lobes = Lobes::All) const {
        // The layered walk rejects unusable samples (bsdf_detail::usable) itself.
        return smooth_ ? flat_.sample_lobes(wo, uc, u, mode, lobes)
                       : rough_.sample_lobes(wo, uc, u, mode, lobes);
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode, Lobes lobes = Lobes::All) const {
        return smooth_ ? SolidAnglePdf(0) : rough_.pdf_lobes(wo, wi, mode, lobes);
    }

private:
    bool smooth_;
    DielectricBxDF flat_;
    RoughDielectricBxDF rough_;
};

// A conductor base: a smooth mirror with the conductor Fresnel term, or a rough conductor.
class ConductorInterface final : public BxDF {
public:
    ConductorInterface(Fresnel fresnel, Vector2f alpha)
        : smooth_(std::max(alpha.x, alpha.y) < 1e-3f), flat_(fresnel.eta, fresnel.k, fresnel.mode),
          rough_(bsdf_detail::ggx_clamped(alpha), fresnel) {}
    ConductorInterface(RoughConductorBxDF rough)
        : smooth_(false), flat_(SampledSpectrum(1), SampledSpectrum(0)), rough_(rough) {}
    std::uint8_t flags() const override { return smooth_ ? flat_.flags() : rough_.flags(); }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        return smooth_ ? Bsdf3() : rough_.f(wo, wi, mode);
    }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        return smooth_ ? flat_.sample(wo, uc, u, mode) : rough_.sample(wo, uc, u, mode);
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        return smooth_ ? SolidAnglePdf(0) : rough_.pdf(wo, wi, mode);
    }

private:
    bool smooth_;
    ConductorBxDF flat_;
    RoughConductorBxDF rough_;
};

} // namespace illum
