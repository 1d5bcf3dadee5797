// The filter pbrt-v4 evaluates Ptex textures with: Ptex's separable B-spline filter (PtexFilter f_bspline,
// no lerp between levels, sharpness 0; Burley & Lacewell 2008), over the footprint the ray differentials
// give in the face's (u, v):
//
// - The filter width along u is |∂u/∂x| + |∂u/∂y| (the bounding box of the footprint), at least one texel
//   of the face; the kernel works at the resolution 2^k with k = ceil(log2(1/width)) (the face's own for a
//   one-texel width, a reduction for wider footprints: ptex_file.h), where the width is between one and two
//   texels. There it is the uniform cubic B-spline (Mitchell-Netravali with B = 1, C = 0) stretched to four
//   widths, B(x) = (3|x|³ - 6x² + 4)/6 for |x| < 1, (2 - |x|)³/6 for |x| < 2, x = (i - (u 2^k - 1/2)) /
//   (width 2^k) for texel i. At a texel centre with the smallest width that gives the weights 1/6, 2/3, 1/6.
// - Wide footprints, as Ptex: a width in [1/4, 1/2) uses the 4 x 4 reduction with the B-spline at unit
//   spacing (the taps widened to even pairs); in [1/2, 1) the 2 x 2 reduction with the cubic Hermite
//   kernel h(x) = 2|x|³ - 3x² + 1 (|x| < 1) at spacing 1/(1.5 width + 0.5), over the four texels from
//   2 floor(u - 1/2); from 1 the face's mean blended with its neighbour's by h(u - 1/2 - floor(u - 1/2)).
// - u and v are clamped to [0, 1] (border mode clamp), wrapped (periodic) or, beyond one face width,
//   black. Taps beyond the face's edge go to the adjacent face across that edge (turned into its frame, at
//   its resolution when that is coarser: pairs of taps summed), and taps beyond a corner to the faces
//   around that corner: the diagonal face at a vertex of valence 4; at valence 5 and more the corner part of
//   the kernel made symmetric (its u and v weights summed) and given to each face around the vertex, its
//   weight rescaled; at valence 2 or 3 none, its weight left out of the normalisation. Main faces and
//   subfaces (of non-quad faces) meet with the kernel moved between their resolutions. Where a face has no
//   adjacent face, the taps go to the edge texels (clamp, periodic) or are dropped (black). The result is
//   divided by the kernel's whole weight. With the edge filter mode "tanvec" the first two channels are
//   turned back from each neighbour's frame (not a constant face's value, as in Ptex).
// - A face flagged "neighbourhood constant" is its constant value. A subface builds its kernel at twice its
//   resolution, as Ptex does, and halves it.
// Checked against Ptex's own filter to float rounding (docs/verification.md, "Ptex textures").
#pragma once

#include "illum/texture/ptex_file.h"

namespace illum {

// The filtered value of `file`'s face at (u, v) with the footprint's derivatives (du/dx, dv/dx) and
// (du/dy, dv/dy): `file.channels` values in [0, 1] for integer data into `out` (at most 4 are written, the
// first ones). A face index outside the file gives 0.
void ptex_filter(const PtexFile& file, int face, float u, float v, float dudx, float dvdx, float dudy,
                 float dvdy, float* out);

} // namespace illum
