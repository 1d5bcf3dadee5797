// The coefficients of the medium that pbrt-v4's "subsurface" material encloses, from its parameters, as
// pbrt-v4 derives them (SubsurfaceMaterial::Create and GetBSSRDF in src/pbrt/materials.cpp,
// SubsurfaceFromDiffuse in src/pbrt/bssrdf.h). The material code reads the ParamSet and calls these with
// plain numbers (or with texture values per shading point / per wavelength).
//
// pbrt-v4's parameters, tried in this order (the first that is present wins; the others go unused):
//   1. "string name": a measured medium (measured_media.h; unknown: error). σ_a, σ_s [mm^-1, used as per
//      scene unit] times "scale". "g" is forced to 0 (the table's σ_s is reduced for Jensen's media; pbrt-v4
//      warns when "g" is non-zero), also for the BSSRDF table: build EffectiveAlbedoTable(eta, 0).
//   2. "spectrum sigma_a" and "spectrum sigma_s" (textures allowed, SpectrumType::Unbounded) [per scene
//      unit]: both or neither (one alone is an error); σ = max(0, "scale" · value).
//   3. "spectrum reflectance" (texture, SpectrumType::Albedo, clamped to [0, 1]) with "spectrum mfp"
//      (texture, Unbounded, default 1) [scene units]: the mean free path is max(0, "scale" · mfp), so here
//      "scale" multiplies the length and divides the coefficients; the single-scattering albedo α is the
//      one whose PBD effective albedo is the reflectance (beam_diffusion.h), σ_s = α / mfp,
//      σ_a = (1 - α) / mfp (σ_t = 1 / mfp).
//   4. none of these: σ_a = (0.0011, 0.0024, 0.014), σ_s = (2.55, 3.21, 3.77) (Jensen's whole milk,
//      [mm^-1]), RGBUnboundedSpectrum in sRGB, times "scale".
// Others: "float scale" 1; "float eta" 1.33 (the BSSRDF table and the dielectric boundary; a float only);
// "float g" 0 (Henyey-Greenstein, for the table); "roughness"/"uroughness"/"vroughness" 0 and
// "remaproughness" true for the boundary's BSDF.
// Textures (2. and 3.) are evaluated where a path enters the shape (textured_subsurface_medium.h).
// Spectral mode: named and default triples are RGBUnboundedSpectrum (MediumSpectrum(Color3)); with
// "reflectance", evaluate reflectance and mfp at each wavelength and call subsurface_from_reflectance per
// value, as pbrt-v4 inverts per wavelength sample.
#pragma once

#include <algorithm>
#include <optional>
#include <string_view>

#include "illum/medium/beam_diffusion.h"
#include "illum/radiometry/color.h"

namespace illum {

// [per scene unit]
struct SubsurfaceCoefficients {
    Color3 sigma_a, sigma_s;
};

// One channel or wavelength [per scene unit].
struct SubsurfaceCoefficient {
    float sigma_a = 0, sigma_s = 0;
};

inline constexpr Color3 kSubsurfaceDefaultSigmaA{0.0011f, 0.0024f, 0.014f};
inline constexpr Color3 kSubsurfaceDefaultSigmaS{2.55f, 3.21f, 3.77f};
inline constexpr float kSubsurfaceDefaultEta = 1.33f;
inline constexpr float kSubsurfaceDefaultG = 0;
inline constexpr float kSubsurfaceDefaultScale = 1;
inline constexpr float kSubsurfaceDefaultMfp = 1;

// 1. "name" with "scale"; nullopt for an unknown name.
std::optional<SubsurfaceCoefficients> subsurface_from_name(std::string_view name, float scale = 1);
// 2. "sigma_a", "sigma_s" with "scale" (negative products clamp to 0, as pbrt-v4's ClampZero).
SubsurfaceCoefficients subsurface_from_sigma(Color3 sigma_a, Color3 sigma_s, float scale = 1);
// 4. Nothing given: pbrt-v4's defaults with "scale".
SubsurfaceCoefficients subsurface_default(float scale = 1);
// 3. "reflectance" and "mfp" with "scale", for one channel or wavelength; `table` built for the material's
// (eta, g). A NaN reflectance counts as 0. A zero mean free path gives infinite coefficients (0 where the
// albedo makes the numerator 0; pbrt-v4 divides and gets NaN there).
SubsurfaceCoefficient subsurface_from_reflectance(float reflectance, float mfp, float scale,
                                                  const EffectiveAlbedoTable& table);
SubsurfaceCoefficients subsurface_from_reflectance(Color3 reflectance, Color3 mfp, float scale,
                                                   const EffectiveAlbedoTable& table);
// 3. for one wavelength's or texel's reflectance and mean free path as pbrt-v4 reads them: the reflectance
// clamped to [0, 1], the mean free path kept at least kSubsurfaceMinMfp (so the coefficients stay finite:
// pbrt-v4's ClampZero lets a zero or negative texel through to a division by zero).
inline constexpr float kSubsurfaceMinMfp = 1e-8f;
inline SubsurfaceCoefficient subsurface_from_reflectance_value(float reflectance, float mfp, float scale,
                                                               const EffectiveAlbedoTable& table) {
    return subsurface_from_reflectance(std::clamp(reflectance, 0.0f, 1.0f),
                                       mfp > kSubsurfaceMinMfp ? mfp : kSubsurfaceMinMfp, scale, table);
}
// The g the material's table must use: 0 with a "name", else "g".
inline float subsurface_table_g(bool has_name, float g) { return has_name ? 0.0f : g; }

} // namespace illum
