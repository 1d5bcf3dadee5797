// Materials turn a surface hit into a BSDF, evaluating their textures there, at the path's wavelengths
// (spectral mode: RGB inputs uplifted, spectra sampled; a dispersive one may terminate the secondary
// wavelengths) or in RGB. The BxDF lives in the
// per-thread scratch arena, so shading allocates nothing on the heap.
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/lambert.h"
#include "illum/bsdf/surface_detail.h"
#include "illum/geometry/surface_hit.h"
#include "illum/medium/medium.h"
#include "illum/radiometry/uplift.h"
#include "illum/texture/texture.h"
#include "illum/util/arena.h"

namespace illum {

// A BxDF placed at a hit: in the frame of the shading normal and the surface's tangent ∂p/∂u, or, for a
// model that looks the same in any frame about the normal (BxDF::isotropic), in one built from the normal
// alone (Frame::from_z: no square root for the path's next direction to wait for).
// `isotropic` is bxdf->isotropic(), given by a caller that keeps it (a shared model).
inline BSDF placed(const BxDF* bxdf, const SurfaceHit& hit, bool isotropic) {
    return BSDF(bxdf, isotropic ? Frame::from_z(hit.ns) : hit.shading_frame());
}
inline BSDF placed(const BxDF* bxdf, const SurfaceHit& hit) { return placed(bxdf, hit, bxdf->isotropic()); }

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

    // The material that shades a hit: itself; a mix picks one of its components (pbrt-v4 resolves a mix
    // before bump mapping, so the chosen material's surface detail applies).
    virtual const Material* resolve(const SurfaceHit&) const { return this; }

    // Whether the material may scatter by a delta lobe (a mirror, smooth glass): false only where that is
    // known not to happen, so a scene without such materials has no caustics to trace from the lights.
    bool may_be_specular = true;
    // pbrt-v4's "normalmap" and "displacement" of this material (null: none), and whether surface detail
    // may apply at its hits at all (its own, or, for a mix, a component's): the one test a material
    // without detail pays.
    std::unique_ptr<const SurfaceDetail> surface_detail;
    bool has_surface_detail = false;
    // Whether a texture of this material (or, for a mix, of a component) filters over the hit's footprint
    // (TextureParams::mark_footprint): only then does the integrator compute the hit's ray differentials
    // (render/texture_footprint.h), so scenes without such textures pay one test per hit.
    bool needs_texture_differentials = false;
};

// Resolves the hit's material (a mix to its component) and applies that material's surface detail to the
// hit's shading geometry (ns, dpdu, dpdv); returns the resolved material (null for none).
inline const Material* apply_surface_detail(SurfaceHit& hit) {
    const Material* m = hit.material ? hit.material->resolve(hit) : nullptr;
    if (m && m->surface_detail) m->surface_detail->apply(hit);
    return m;
}

// The BSDF at a hit, as pbrt-v4's SurfaceInteraction::GetBSDF builds it: the material's normal or bump map
// first changes the hit's shading geometry (so the integrator's cosines |wi · ns| see it too), then the
// material makes its BSDF there. No material: an empty BSDF (an interface).
inline BSDF surface_bsdf(SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) {
    const Material* m = hit.material;
    if (!m) return BSDF();
    if (m->has_surface_detail) [[unlikely]] {
        m = apply_surface_detail(hit);
        if (!m) return BSDF();
    }
    return m->bsdf(hit, lambda, arena);
}

class DiffuseMaterial final : public Material {
public:
    explicit DiffuseMaterial(const ColorTexture* reflectance) : reflectance_(reflectance) {
        may_be_specular = false;
    }
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        SampledSpectrum r = reflectance_->albedo(hit, lambda);
        return placed(arena.make<LambertBxDF>(r), hit);
    }
    Color3 albedo(const SurfaceHit& hit) const override {
        return clamp(reflectance_->evaluate(hit), 0.0f, 1.0f);
    }

private:
    const ColorTexture* reflectance_;
};

} // namespace illum
