// What the renderer knows about a ray's hit: position with its error bound, the geometric normal (on
// the shape's outward side), the shading frame, uv, and what the surface is made of.
#pragma once

#include <cstdint>

#include "illum/geometry/medium_interface.h"
#include "illum/geometry/ray.h"
#include "illum/geometry/shading_partials.h"
#include "illum/math/frame.h"
#include "illum/math/transform.h"
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
    // The shading partials ∂p/∂v, ∂n/∂u, ∂n/∂v: zero until complete_shading_partials() computes them
    // (with pbrt-v4's ∂p/∂u in dpdu), which bump and normal mapping do (bsdf/surface_detail.h).
    Vector3f dpdv;
    Normal3f dndu, dndv;
    // Where complete_shading_partials() finds the surface: the shape, the point on it in the shape's terms,
    // and the placement of the instance the hit is in (null: none).
    const ShadingPartialsSource* partials_source = nullptr;
    Point3f local;
    const Transform* world_from_instance = nullptr;
    const Material* material = nullptr;
    const Light* area_light = nullptr; // the emitter on this surface, if any
    std::uint32_t geom_id = 0, prim_id = 0;
    // The media on either side: the surface's interface where it separates two media, else both sides are
    // `medium`, the medium of the ray that found the hit.
    const MediumInterface* medium_interface = nullptr;
    const Medium* medium = nullptr;
    float time = 0; // the time of the ray that found the hit; rays spawned here keep it

    // The shape's partials at the hit, in world space (all zero when the shape gives none).
    ShadingPartials world_partials() const {
        if (!partials_source) return {};
        ShadingPartials s = partials_source->shading_partials(prim_id, local);
        if (world_from_instance) {
            const Transform& w = *world_from_instance;
            s = {w(s.dpdu), w(s.dpdv), w(s.dndu), w(s.dndv), w(s.geometric_dpdu), w(s.geometric_dpdv)};
        }
        return s;
    }
    // Sets dpdu, dpdv, dndu, dndv to the shape's shading partials at the hit, in world space.
    void complete_shading_partials() {
        if (!partials_source) return;
        set_shading_partials(world_partials());
    }
    void set_shading_partials(const ShadingPartials& s) {
        dpdu = s.dpdu;
        dpdv = s.dpdv;
        dndu = s.dndu;
        dndv = s.dndv;
    }

    // The shading frame: +z is the shading normal, x follows dpdu.
    // (Always inlined, as Frame::from_xz: the frame goes from registers into the BSDF, not through memory.)
    [[gnu::always_inline]] Frame shading_frame() const { return Frame::from_xz(dpdu, Vector3f(ns)); }

    // The medium a ray leaving the surface along w travels in.
    const Medium* medium_for(Vector3f w) const {
        if (!medium_interface) return medium;
        return dot(w, n) > 0 ? medium_interface->outside : medium_interface->inside;
    }

    // Always inlined, as the functions they call (geometry/ray.h).
    [[gnu::always_inline]] Ray spawn_ray(Vector3f d) const {
        Ray r = illum::spawn_ray(p, p_error, n, d);
        r.medium = medium_for(d);
        r.time = time;
        return r;
    }
    [[gnu::always_inline]] Ray spawn_ray_to(Point3f target) const {
        Ray r = illum::spawn_ray_to(p, p_error, n, target);
        r.medium = medium_for(target - p);
        r.time = time;
        return r;
    }
};

} // namespace illum
