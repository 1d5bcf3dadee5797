// pbrt-v4's displacement of a "plymesh" by its "displacement" float texture (TriQuadMesh::Displace):
// 1. without vertex normals, each vertex gets the normalised sum of its faces' unit normals
//    (v1 - v0) × (v2 - v1);
// 2. every triangle whose edges are not all shorter than max_edge (measured in world space: pbrt-v4's
//    "edgelength" times Option "displacementedgescale") is split at the midpoint of its longest edge, and
//    both halves are refined the same way; a split edge's midpoint is shared by the triangles on either
//    side (its normal the normalised sum of the ends', its uv their mean), so the mesh stays watertight;
//    each piece keeps its triangle's face index (pbrt-v4 keeps the per-face list unchanged, which no longer
//    fits the refined mesh);
// 3. each vertex moves along its (interpolated, not renormalised) normal by the texture's value at its
//    object-space point and uv, d(p, uv) n;
// 4. the normals are computed again from the displaced triangles, as in step 1.
// pbrt-v4 requires the mesh's uv; so does this (an error otherwise).
#pragma once

#include "illum/geometry/triangle_mesh.h"
#include "illum/math/transform.h"
#include "illum/texture/texture.h"

namespace illum {

// The normalised sums of the faces' unit normals (v1 - v0) × (v2 - v1) at each vertex (zero where no face
// with an area touches it): pbrt-v4's TriQuadMesh::ComputeNormals.
std::vector<Normal3f> vertex_normals(const TriangleMesh& mesh);

// Refines `mesh` (object space, with uv) until every edge is shorter than max_edge > 0 in world space.
// Throws illum::Error (with `what` in the message) when that would take more than max_triangles triangles.
void refine_to_edge_length(TriangleMesh& mesh, const Transform& world_from_object, float max_edge,
                           std::size_t max_triangles);

// Steps 1-4 above on `mesh` (object space, with uv).
void displace_mesh(TriangleMesh& mesh, const FloatTexture& displacement, const Transform& world_from_object,
                   float max_edge, std::size_t max_triangles = std::size_t(1) << 27);

} // namespace illum
