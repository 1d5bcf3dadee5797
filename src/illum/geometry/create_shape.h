// The geometry of a Shape directive: pbrt-v4's trianglemesh, plymesh, bilinearmesh (bilinear patches),
// sphere, disk, cylinder and curve, in world space, with its alpha cut-out. The scene builder adds the result
// to the accelerator and gives it its material and area light.
#pragma once

#include <memory>
#include <optional>

#include "illum/geometry/analytic_shape.h"
#include "illum/geometry/bilinear_patch.h"
#include "illum/geometry/curves.h"
#include "illum/geometry/triangle_mesh.h"
#include "illum/param/entity.h"
#include "illum/texture/texture_params.h"

namespace illum {

struct ShapeGeometry {
    std::unique_ptr<TriangleMesh> mesh;         // a mesh, in world space and finalized, or
    std::unique_ptr<BilinearPatchMesh> patches; // bilinear patches, in world space and finalized, or
    std::unique_ptr<AnalyticShape> analytic;    // an analytic shape (its alpha set), or
    std::unique_ptr<Curves> curves;             // curve segments (in world space)
    const FloatTexture* alpha = nullptr;        // pbrt-v4's "alpha" cut-out; nullptr when opaque
};

// nullopt when the shape is removed (constant alpha 0), recognised but skipped (warned), or its file
// cannot be read (recorded in the diagnostics, so every missing file of a scene is reported together).
// displacement_edge_scale: pbrt-v4's Option "displacementedgescale", which scales plymesh's "edgelength".
std::optional<ShapeGeometry> create_shape(const ShapeDesc& s, TextureParams& textures,
                                          float displacement_edge_scale = 1);

} // namespace illum
