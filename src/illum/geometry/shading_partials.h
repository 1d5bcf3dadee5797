// The shading geometry's partial derivatives at a surface point, as pbrt-v4's SurfaceInteraction::shading
// holds them (∂p/∂u, ∂p/∂v, and ∂n/∂u, ∂n/∂v of the unflipped normal). Only bump and normal mapping
// need them, so a hit records where it lies on its shape and computes them on demand
// (SurfaceHit::complete_shading_partials): a render without surface detail pays a few stores per hit.
#pragma once

#include <cstdint>

#include "illum/math/vector.h"

namespace illum {

struct ShadingPartials {
    Vector3f dpdu, dpdv;
    Normal3f dndu, dndv;
    // The surface's own ∂p/∂u, ∂p/∂v (pbrt-v4's Interaction::dpdu, dpdv), which vertex normals do not
    // change: what the texture footprint's ∂u/∂x... are solved from (geometry/ray_differentials.h).
    Vector3f geometric_dpdu, geometric_dpdv;
};

// A shape that can give the partials at one of its points, in its own (instance) space. `local` says
// where: a triangle's barycentrics (b1, b2, -), an analytic shape's object-space point.
class ShadingPartialsSource {
public:
    virtual ShadingPartials shading_partials(std::uint32_t prim, Point3f local) const = 0;

protected:
    ~ShadingPartialsSource() = default;
};

} // namespace illum
