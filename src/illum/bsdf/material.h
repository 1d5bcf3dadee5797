// Materials turn a surface hit into a BSDF, evaluating their textures there. The BxDF lives in the
// per-thread scratch arena, so shading allocates nothing on the heap.
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/lambert.h"
#include "illum/geometry/surface_hit.h"
#include "illum/texture/texture.h"
#include "illum/util/arena.h"

namespace illum {

class Material {
public:
    virtual ~Material() = default;
    virtual BSDF bsdf(const SurfaceHit& hit, ScratchArena& arena) const = 0;
    // The reflectance a denoiser or the albedo pass shows (hemispherical albedo at normal incidence for
    // simple models; an estimate otherwise).
    virtual Color3 albedo(const SurfaceHit& hit) const = 0;
};

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const ColorTexture* reflectance) : reflectance_(reflectance) {}
    BSDF bsdf(const SurfaceHit& hit, ScratchArena& arena) const override {
        Color3 r = clamp(reflectance_->evaluate(hit), 0.0f, 1.0f);
        return BSDF(arena.make<LambertBxDF>(r), hit.shading_frame());
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return clamp(reflectance_->evaluate(hit), 0.0f, 1.0f);
    }

private:
    const ColorTexture* reflectance_;
};

} // namespace illum
