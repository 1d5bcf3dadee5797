// A hit's texture footprint, as pbrt-v4's SurfaceInteraction::ComputeDifferentials gives it, and the ray
// differentials a path carries (geometry/ray_differentials.h): camera rays start with them (scaled to the
// spacing of the pixel's samples, max(1/8, 1/sqrt(spp)) pixels), perfectly specular reflection and
// refraction carry them on, any other scattering drops them. A hit found by a ray without them (after a
// diffuse bounce, on a light path) takes the camera's approximation (Camera::approximate_dp_dxy).
//
// The cost falls only on scenes with filtered textures: camera rays carry differentials only when
// Scene::texture_filtering is set, and a hit computes its footprint only when its material filters
// (Material::needs_texture_differentials) or the ray carries differentials (a mirror on the way to a
// texture needs its own footprint to carry them).
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/material.h"
#include "illum/geometry/ray_differentials.h"
#include "illum/render/scene.h"

namespace illum {

// Whether a hit needs its footprint (one test for scenes without filtered textures).
inline bool needs_footprint(const SurfaceHit& hit, const RayDifferentials& rd) {
    return rd.valid || (hit.material && hit.material->needs_texture_differentials);
}

// Sets the hit's ∂p/∂x, ∂p/∂y and ∂u/∂x... (and its shading partials, which carrying differentials
// through a specular bounce needs), from rd when it is valid and meets the tangent plane, else from the
// camera's approximation for spp samples per pixel (scaled as the camera rays' differentials are: not at
// all when pixel jitter is disabled, as in pbrt-v4).
inline void compute_footprint(SurfaceHit& hit, const RayDifferentials& rd, const Scene& scene, int spp) {
    ShadingPartials s = hit.world_partials();
    if (hit.partials_source) hit.set_shading_partials(s);
    Vector3f dpdx, dpdy;
    if (!(rd.valid && footprint_from_differentials(hit, rd, &dpdx, &dpdy)))
        scene.camera->approximate_dp_dxy(
            hit.p, hit.n, scene.request.disable_pixel_jitter ? 1.0f : ray_differential_scale(spp), &dpdx,
            &dpdy);
    set_uv_derivatives(hit, dpdx, dpdy, s.geometric_dpdu, s.geometric_dpdv);
}

// At a hit found by a ray without differentials (bidirectional and light paths, direct lighting): the
// camera's approximation where the material filters.
inline void footprint_from_camera(SurfaceHit& hit, const Scene& scene, int spp) {
    if (hit.material && hit.material->needs_texture_differentials) [[unlikely]]
        compute_footprint(hit, RayDifferentials{}, scene, spp);
}

// The differentials of the ray a BSDF sample continues the path with: carried through perfectly specular
// reflection or transmission, none otherwise.
inline RayDifferentials continue_differentials(const SurfaceHit& hit, const RayDifferentials& rd,
                                               const BSDFSample& bs) {
    if (!rd.valid || !bs.is_specular()) return {};
    return specular_differentials(hit, rd, bs.wi, bs.is_reflection(), bs.eta);
}

} // namespace illum
