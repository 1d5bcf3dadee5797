// Surface detail that changes only the shading geometry: pbrt-v4's "normalmap" (a tangent-space normal
// image) and "displacement" (a float texture, bump mapping), parameters of every material but "mix" and
// "interface". Applied to a hit once, where its BSDF is built (pbrt-v4's SurfaceInteraction::GetBSDF):
//
// - Normal map: the image, read with linear encoding, is looked up bilinearly at (u, 1 - v) with repeat
//   wrapping; its value c in [0, 1]³ gives the tangent-space normal n_t = normalize(2c - 1) in the frame
//   (x = normalize(∂p/∂u), y = n × x, z = n) of the shading geometry. ∂p/∂u is then n_t's Gram-Schmidt
//   complement of the old ∂p/∂u (its length kept) and ∂p/∂v = normalize(n_t × ∂p/∂u) |∂p/∂v|.
// - Bump map (Blinn 1978, "Simulation of wrinkled surfaces"; PBR 4th ed. §10.5.1): the surface displaced
//   along the shading normal, p' = p + d(u, v) n, has ∂p'/∂u = ∂p/∂u + ∂d/∂u n + d ∂n/∂u, and likewise
//   in v; ∂d/∂u is the forward difference
//   (d(u + Δu) - d(u)) / Δu with the texture evaluated at p + Δu ∂p/∂u, uv + (Δu, 0). pbrt-v4 takes Δu
//   from the ray differentials, .5 (|∂u/∂x| + |∂u/∂y|), and .0005 when that is 0; illum carries no ray
//   differentials, so Δu = Δv = .0005 always (pbrt-v4's own value for rays without differentials).
//
// The shading normal becomes normalize(∂p'/∂u × ∂p'/∂v), turned to the side of the geometric normal; the
// normal map wins when a material has both (as in pbrt-v4).
#pragma once

#include <memory>

#include "illum/geometry/surface_hit.h"
#include "illum/image/image.h"
#include "illum/param/entity.h"
#include "illum/texture/pbrt_textures.h"
#include "illum/texture/texture.h"
#include "illum/texture/texture_params.h"

namespace illum {

class SurfaceDetail {
public:
    // pbrt-v4's finite-difference step in u and v where the hit has no footprint (∂u/∂x... all zero).
    static constexpr float kBumpDelta = .0005f;

    // Either may be null (not both, for the detail to do anything).
    SurfaceDetail(const FloatTexture* displacement, std::shared_ptr<const Image> normal_map);

    // Completes the hit's shading partials (SurfaceHit::complete_shading_partials), then replaces its
    // shading normal ns and ∂p/∂u, ∂p/∂v by the perturbed ones. Leaves ns as it was where the perturbed
    // tangents are degenerate (parallel or not finite).
    void apply(SurfaceHit& hit) const;
    // Whether the detail bumps by a displacement (whose finite differences step by the hit's footprint).
    bool bumps() const { return displacement_ != nullptr; }

    // The perturbed ∂p/∂u, ∂p/∂v at a hit whose partials are complete, before the normal is formed from
    // them.
    void normal_map_tangents(const SurfaceHit& hit, Vector3f* dpdu, Vector3f* dpdv) const;
    void bump_tangents(const SurfaceHit& hit, Vector3f* dpdu, Vector3f* dpdv) const;

    const FloatTexture* displacement() const { return displacement_; }
    bool has_normal_map() const { return normal_map_ != nullptr; }

private:
    const FloatTexture* displacement_;
    std::shared_ptr<const Image> normal_map_image_;
    std::unique_ptr<ImageTextureData> normal_map_;
};

// A material's "displacement" (float or float texture) and "normalmap" (an image file name, resolved by the
// parser against the scene's folder), or nullptr when it has neither. The image is read once per file
// (with linear encoding: 8-bit values v/255, float files as they are); an unreadable file is recorded in
// the diagnostics at the parameter's position (reported with every other missing file of the scene).
// Throws illum::Error at the parameter for a wrong type or an undefined texture.
std::unique_ptr<const SurfaceDetail> read_surface_detail(const EntityDesc& material, TextureParams& textures);

} // namespace illum
