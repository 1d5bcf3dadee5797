// pbrt-v4's "curve" shape as cubic Bézier segments in world space, for Embree's native curve primitives.
// pbrt-v4 turns every curve into cubic Bézier segments (a quadratic one elevated, a uniform B-spline
// converted), each with its own u ∈ [0, 1] and its width interpolated linearly in u between the curve's
// width0 and width1 at the segment's ends; so does this. The types:
//   flat      a ribbon that always faces the ray (Embree's FLAT_BEZIER_CURVE; pbrt-v4's own intersector
//             makes the same surface);
//   cylinder  the same ray-facing ribbon whose normal is turned about the curve by -90°..90° across its
//             width so that it shades like a tube (pbrt-v4's Curve::RecursiveIntersect does exactly this;
//             Embree's ROUND curves would be a true swept tube, a different surface and slower);
//   ribbon    oriented by normals N given at the segments' ends (Embree's NORMAL_ORIENTED_BEZIER_CURVE;
//             pbrt-v4 instead narrows a ray-facing ribbon by |n·d|).
// A hit's (u, v): u along the segment, v ∈ [0, 1] across its width, v = 1/2 on the axis, increasing
// towards dp/dv = d × dp/du (flat, cylinder) or n × dp/du (ribbon), as pbrt-v4 defines them; the hair
// material reads h = -1 + 2v.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "illum/geometry/surface_hit.h"
#include "illum/math/bounds.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

enum class CurveType : std::uint8_t { Flat, Cylinder, Ribbon };

// Many curve segments of one type and orientation (the accelerator merges the curves of one material into
// one Embree geometry).
struct Curves {
    CurveType type = CurveType::Flat;
    bool flip_normal = false;                    // ReverseOrientation xor a handedness-swapping transform
    std::vector<std::array<Point3f, 4>> cp;      // each segment's Bézier control points
    std::vector<std::array<float, 2>> width;     // each segment's width at u = 0 and u = 1
    std::vector<std::array<Normal3f, 2>> normal; // ribbons: the unit normal at u = 0 and u = 1
    // Embree's tessellation rate (ray-facing quads per segment), from pbrt-v4's own flatness criterion:
    // 2^r pieces, r = ⌊log4(√2·6·L0 / (8ε))⌋, L0 the largest second difference of the control points and
    // ε = width / 20 (Curve::IntersectRay's refinement depth); at least Embree's default of 4.
    int tessellation = 4;

    std::size_t segment_count() const { return cp.size(); }
    void append(const Curves& other);
    Bounds3f bounds() const;
    // The hit on segment `seg` at curve parameter u (Embree's hit u) and distance t along `ray`.
    void fill_hit(std::uint32_t seg, float u, float t, const Ray& ray, SurfaceHit* hit) const;
};

// The cubic Bézier curve through control points c at u, and its derivative (de Casteljau).
Point3f bezier_point(const std::array<Point3f, 4>& c, float u, Vector3f* derivative = nullptr);

// pbrt-v4's "curve" shape (P, basis, degree, type, width, width0, width1, N, splitdepth) in world space.
// Throws illum::Error at the offending parameter for a wrong count of control points or normals, an unknown
// basis or type, a degree other than 2 or 3, or a negative or non-finite width.
std::unique_ptr<Curves> create_curves(const ShapeDesc& s, Diagnostics& diag);

} // namespace illum
