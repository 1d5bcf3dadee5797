// Materials turn a surface hit into a BSDF, evaluating their textures there, at the path's wavelengths
// (spectral mode: RGB inputs uplifted, spectra sampled; a dispersive one may terminate the secondary
// wavelengths) or in RGB. The BxDF lives in the
// per-thread scratch arena, so shading allocates nothing on the heap.
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/lambert.h"
#include "illum/geometry/surface_hit.h"
#include "illum/medium/medium.h"
#include "illum/radiometry/uplift.h"
#include "illum/texture/texture.h"
#include "illum/util/arena.h"

namespace illum {

class Material {
public:
    virtual ~Material() = default;
    virtual BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const = 0;
    // The reflectance a denoiser or the albedo pass shows (hemispherical albedo at normal incidence for
    // simple models; an estimate otherwise).
    virtual Color3 albedo(const SurfaceHit& hit) const = 0;
    // pbrt-v4's "interface": a boundary between media with no surface; light crosses it unchanged, and
    // shadow rays pass through it.
    virtual bool is_interface() const { return false; }
    // The participating medium the material's surface encloses (pbrt-v4's "subsurface": scattering inside
    // the shape), or none. The scene makes it the inside of the shape's MediumInterface.
    virtual const Medium* interior() const { return nullptr; }

    // Whether the material may scatter by a delta lobe (a mirror, smooth glass): false only where that is
    // known not to happen, so a scene without such materials has no caustics to trace from the lights.
    bool may_be_specular = true;
};

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const ColorTexture* reflectance) : reflectance_(reflectance) {
        may_be_specular = false;
    }
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        SampledSpectrum r = reflectance_->albedo(hit, lambda);
        return BSDF(arena.make<LambertBxDF>(r), hit.shading_frame());
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return clamp(reflectance_->evaluate(hit), 0.0f, 1.0f);
    }

private:
    const ColorTexture* reflectance_;
};

} // namespace illum
