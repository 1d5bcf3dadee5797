// pbrt-v4's "measured" material (MeasuredMaterial): the BRDF of an RGL `.bsdf` file (bsdf/measured.h),
// the same at every point; its tables are shared, the BxDF placed per hit with the path's wavelengths.
#pragma once

#include <memory>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/material.h"
#include "illum/bsdf/measured.h"

namespace illum {

class MeasuredMaterial final : public Material {
public:
    explicit MeasuredMaterial(std::shared_ptr<const RglBrdf> data) : data_(std::move(data)) {
        may_be_specular = false;
        // The albedo pass shows the directional albedo at normal incidence (RGB), found once.
        MeasuredBxDF bxdf(data_.get(), nullptr);
        Rgb64 a = albedo_quadrature(bxdf, Vector3f(0, 0, 1), 64, true);
        albedo_ = Color3(float(a[0]), float(a[1]), float(a[2]));
    }
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        return placed(arena.make<MeasuredBxDF>(data_.get(), &lambda), hit);
    }
    Color3 albedo(const SurfaceHit&) const override { return albedo_; }

private:
    std::shared_ptr<const RglBrdf> data_;
    Color3 albedo_;
};

} // namespace illum
