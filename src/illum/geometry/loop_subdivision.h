// pbrt-v4's "loopsubdiv" shape: Loop subdivision (C. Loop, "Smooth Subdivision Surfaces Based on Triangles",
// 1987; PBR 3rd ed. §3.8) of a triangle mesh, `levels` times, then every vertex moved to its limit position
// and given the limit surface's normal, giving a triangle mesh with F·4^levels faces.
//
// Each level splits every triangle (a, b, c) into (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca):
// - an even (old) vertex v of valence n moves to (1 - n β) v + β Σ ring, β = 3/16 for n = 3 and 3/(8n)
//   otherwise; on a boundary to 3/4 v + 1/8 (r0 + r1), r0 and r1 its two neighbours along the boundary;
// - an odd (new) vertex on edge (a, b) is 3/8 (a + b) + 1/8 (c + d), c and d the vertices opposite the edge;
//   on a boundary edge (a + b) / 2.
// The limit position is (1 - n γ) v + γ Σ ring with γ = 1 / (n + 3 / (8 β)); on a boundary 3/5 v +
// 1/5 (r0 + r1). The limit normal is S × T of the tangents S = Σ cos(2πj/n) r_j, T = Σ sin(2πj/n) r_j over
// the ring in pbrt-v4's order (each next neighbour across the edge from v to the last one), and on a
// boundary S = r_last - r_0 with T from pbrt-v4's boundary masks by valence. Those normals point to the side
// opposite the winding's (p0 - p2) × (p1 - p2), as pbrt-v4's do; the mesh's geometric normals then turn to
// them, as for any mesh with normals.
#pragma once

#include <cstdint>
#include <vector>

#include "illum/math/vector.h"

namespace illum {

struct SubdividedMesh {
    std::vector<Point3f> p;
    std::vector<Normal3f> n;
    std::vector<std::uint32_t> indices; // three per triangle
};

// `indices` (three per triangle, each < p.size()) and `levels` >= 0 are the caller's to check.
SubdividedMesh loop_subdivide(const std::vector<Point3f>& p, const std::vector<int>& indices, int levels);

} // namespace illum
