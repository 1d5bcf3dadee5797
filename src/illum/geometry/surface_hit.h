// What the renderer knows about a ray's hit: position with its error bound, the geometric normal (on
// the shape's outward side), the shading frame, uv, and what the surface is made of.
#pragma once

#include <cstdint>

#include "illum/geometry/ray.h"
#include "illum/math/frame.h"
#include "illum/texture/texture.h"

namespace illum {

class Material;
class Light;

// p, n and uv are the TextureEvalContext part (textures evaluate at a hit directly).
struct SurfaceHit : TextureEvalContext {
    Vector3f p_error;
    float t = 0;
    Vector3f wo;   // towards the ray origin, normalised
    Normal3f ns;   // shading normal, on the same side as n
    Vector3f dpdu; // tangent along u (for anisotropic models), may be zero
    const Material* material = nullptr;
    const Light* area_light = nullptr; // the emitter on this surface, if any
    std::uint32_t geom_id = 0, prim_id = 0;

    // The shading frame: +z is the shading normal, x follows dpdu.
    Frame shading_frame() const { return Frame::from_xz(dpdu, Vector3f(ns)); }

    Ray spawn_ray(Vector3f d) const { return illum::spawn_ray(p, p_error, n, d); }
    Ray spawn_ray_to(Point3f target) const { return illum::spawn_ray_to(p, p_error, n, target); }
};

} // namespace illum
