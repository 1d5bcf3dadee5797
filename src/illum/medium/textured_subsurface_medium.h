// The medium inside a "subsurface" material whose coefficients are textured (pbrt-v4 takes spectrum
// textures for "sigma_a", "sigma_s" (Unbounded), "reflectance" (Albedo) and "mfp" (Unbounded)): evaluated
// where a path enters the shape (entry_medium.h), as pbrt-v4's SubsurfaceMaterial::GetBSSRDF evaluates them
// at the BSSRDF's entry point:
//   sigma_a, sigma_s:  σ = max(0, scale · value) (pbrt-v4's ClampZero);
//   reflectance, mfp:  subsurface_from_reflectance_value (subsurface_coefficients.h) per channel (RGB mode)
//                      or per wavelength (spectral mode: the texture's RGB uplifted, as a reflectance or an
//                      unbounded value, at each of the path's wavelengths, and inverted there, as pbrt-v4
//                      inverts per wavelength sample).
// One of a pair may be a constant (a "spectrum" constant keeps its spectrum in spectral mode).
#pragma once

#include <memory>

#include "illum/medium/beam_diffusion.h"
#include "illum/medium/entry_medium.h"
#include "illum/radiometry/densely_sampled_spectrum.h"

namespace illum {

// One of the material's coefficient parameters: a texture (constants are constant textures), and a
// constant's spectrum when the scene gave one.
struct SubsurfaceParam {
    const ColorTexture* texture = nullptr;
    std::shared_ptr<const DenselySampledSpectrum> spectrum;
    // The value at `at`, at the path's wavelengths (RGB mode: the colour).
    SampledSpectrum at(const TextureEvalContext& at, const SampledWavelengths& lambda, UpliftKind kind) const;
};

class TexturedSubsurfaceMedium final : public EntryEvaluatedMedium {
public:
    // "sigma_a" and "sigma_s".
    static std::unique_ptr<TexturedSubsurfaceMedium>
    from_sigma(SubsurfaceParam sigma_a, SubsurfaceParam sigma_s, float scale, float g);
    // "reflectance" and "mfp", with the effective albedo table of the material's (eta, g).
    static std::unique_ptr<TexturedSubsurfaceMedium>
    from_reflectance(SubsurfaceParam reflectance, SubsurfaceParam mfp, float scale, float eta, float g);

    void evaluate(const TextureEvalContext& at, const SampledWavelengths& lambda,
                  EntryMedium* out) const override;

    // Walked without an entry point (only a ray that starts inside without crossing the boundary: an area
    // light on the shape emitting inwards): the textures at the point with uv (0, 0).
    bool is_emissive() const override { return false; }
    bool is_homogeneous() const override { return true; }
    MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const override;
    MajorantIterator sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const override;

private:
    TexturedSubsurfaceMedium(SubsurfaceParam a, SubsurfaceParam b, float scale, float g,
                             std::unique_ptr<EffectiveAlbedoTable> table)
        : a_(std::move(a)), b_(std::move(b)), scale_(scale), g_(g), table_(std::move(table)) {}

    SubsurfaceParam a_, b_; // sigma_a and sigma_s, or reflectance and mfp (with table_)
    float scale_, g_;
    std::unique_ptr<EffectiveAlbedoTable> table_; // null: sigma_a and sigma_s
};

} // namespace illum
