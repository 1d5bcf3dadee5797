// A material whose parameters are all constant: in RGB mode one BxDF, built once and shared by every hit
// and thread (BxDFs are immutable), so shading places nothing in the arena at all. In spectral mode its
// values depend on the path's wavelengths: the model is placed per hit (`spectral`, the same model with
// the same constants), or, for a model that cannot be placed (the measured one, tabulated in RGB), the
// shared BxDF's RGB values are uplifted as unbounded spectra (RgbUpliftBxDF).
#pragma once

#include <memory>

#include "illum/bsdf/material.h"

namespace illum {

// An RGB-valued BxDF seen at a path's wavelengths: its values uplifted, its directions and densities as
// they are.
class RgbUpliftBxDF final : public BxDF {
public:
    RgbUpliftBxDF(const BxDF* rgb, const SampledWavelengths& lambda) : rgb_(rgb), lambda_(lambda) {}
    std::uint8_t flags() const override { return rgb_->flags(); }
    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        return Bsdf3(uplift_unbounded(rgb_->f(wo, wi, mode).rgb(), lambda_));
    }
    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        auto s = rgb_->sample(wo, uc, u, mode);
        if (s) s->f = Bsdf3(uplift_unbounded(s->f.rgb(), lambda_));
        return s;
    }
    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode mode) const override {
        return rgb_->pdf(wo, wi, mode);
    }
    bool reads_lobe_sample() const override { return rgb_->reads_lobe_sample(); }
    bool isotropic() const override { return rgb_->isotropic(); }

private:
    const BxDF* rgb_;
    SampledWavelengths lambda_;
};

class SharedBxDFMaterial final : public Material {
public:
    // albedo: what the albedo pass shows (e.g. the directional albedo at normal incidence).
    SharedBxDFMaterial(std::unique_ptr<BxDF> bxdf, Color3 albedo,
                       std::unique_ptr<Material> spectral = nullptr)
        : bxdf_(std::move(bxdf)), albedo_(albedo), spectral_(std::move(spectral)),
          isotropic_(bxdf_->isotropic()) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        if (!lambda.spectral()) return placed(bxdf_.get(), hit, isotropic_);
        if (spectral_) return spectral_->bsdf(hit, lambda, arena);
        return placed(arena.make<RgbUpliftBxDF>(bxdf_.get(), lambda), hit);
    }
    Color3 albedo(const SurfaceHit&) const override { return albedo_; }
    const BxDF& bxdf() const { return *bxdf_; }

private:
    std::unique_ptr<BxDF> bxdf_;
    Color3 albedo_;
    std::unique_ptr<Material> spectral_;
    bool isotropic_; // bxdf_->isotropic(), kept: placed() without a virtual call per hit
};

} // namespace illum
