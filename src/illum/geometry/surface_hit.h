// What the renderer knows about a ray's hit: position with its error bound, the geometric normal (on
// the shape's outward side), the shading frame, uv, and what the surface is made of.
#pragma once

#include <cstdint>

#include "illum/geometry/medium_interface.h"
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
    // The media on either side: the surface's interface where it separates two media, else both sides are
    // `medium`, the medium of the ray that found the hit.
    const MediumInterface* medium_interface = nullptr;
    const Medium* medium = nullptr;
    float time = 0; // the time of the ray that found the hit; rays spawned here keep it

    // The shading frame: +z is the shading normal, x follows dpdu.
    Frame shading_frame() const { return Frame::from_xz(dpdu, Vector3f(ns)); }

    // The medium a ray leaving the surface along w travels in.
    const Medium* medium_for(Vector3f w) const {
        if (!medium_interface) return medium;
        return dot(w, n) > 0 ? medium_interface->outside : medium_interface->inside;
    }

    Ray spawn_ray(Vector3f d) const {
        Ray r = illum::spawn_ray(p, p_error, n, d);
        r.medium = medium_for(d);
        r.time = time;
        return r;
    }
    Ray spawn_ray_to(Point3f target) const {
        Ray r = illum::spawn_ray_to(p, p_error, n, target);
        r.medium = medium_for(target - p);
        r.time = time;
        return r;
    }
};

} // namespace illum
