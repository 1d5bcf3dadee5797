// pbrt-v4's "subsurface" material, rendered exactly: a dielectric boundary (smooth or rough, its "eta"
// and roughness) around a homogeneous scattering medium with the coefficients pbrt-v4 derives from the
// material's parameters (medium/subsurface_coefficients.h: a measured medium by "name", "sigma_a" and
// "sigma_s", or "reflectance" with "mfp"). volpath walks inside the shape through that medium (a
// volumetric random walk, as Cycles' random-walk subsurface scattering), instead of pbrt-v4's tabulated
// diffusion BSSRDF (photon beam diffusion), which approximates the same light transport. Textured
// coefficients (any of the four may be a spectrum texture, as in pbrt-v4) make the interior a
// TexturedSubsurfaceMedium (medium/textured_subsurface_medium.h): evaluated where a path enters the shape
// (pbrt-v4 evaluates its textures at the BSSRDF's entry point) and homogeneous for the walk inside.
#pragma once

#include <memory>

#include "illum/bsdf/pbrt_materials.h"

namespace illum {

class SubsurfaceMaterial final : public Material {
public:
    SubsurfaceMaterial(DispersiveScalar eta, RoughnessParams rough, std::unique_ptr<Medium> interior)
        : boundary_(std::move(eta), rough), interior_(std::move(interior)) {}
    BSDF bsdf(const SurfaceHit& hit, SampledWavelengths& lambda, ScratchArena& arena) const override {
        return boundary_.bsdf(hit, lambda, arena);
    }
    Color3 albedo(const SurfaceHit& hit) const override { return boundary_.albedo(hit); }
    const Medium* interior() const override { return interior_.get(); }

private:
    DielectricMaterial boundary_;
    std::unique_ptr<Medium> interior_;
};

} // namespace illum
