// A material whose parameters are all constant: one BxDF, built once and shared by every hit and thread
// (BxDFs are immutable), so shading places nothing in the arena at all.
#pragma once

#include <memory>

#include "illum/bsdf/material.h"

namespace illum {

class SharedBxDFMaterial final : public Material {
public:
    // albedo: what the albedo pass shows (e.g. the directional albedo at normal incidence).
    SharedBxDFMaterial(std::unique_ptr<BxDF> bxdf, Color3 albedo) : bxdf_(std::move(bxdf)), albedo_(albedo) {}
    BSDF bsdf(const SurfaceHit& hit, ScratchArena&) const override {
        return BSDF(bxdf_.get(), hit.shading_frame());
    }
    Color3 albedo(const SurfaceHit&) const override { return albedo_; }
    const BxDF& bxdf() const { return *bxdf_; }

private:
    std::unique_ptr<BxDF> bxdf_;
    Color3 albedo_;
};

} // namespace illum
