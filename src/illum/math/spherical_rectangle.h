// Uniform sampling of the solid angle a rectangle subtends (Ureña, Fajardo and King, "An Area-Preserving
// Parametrization for Spherical Rectangles", EGSR 2013), and its inverse.
//
// The rectangle is the corner s and two orthogonal edges ex, ey; in the frame x = ex/|ex|, y = ey/|ey|,
// z = x × y (z turned away from the rectangle, so z0 < 0) it spans [x0, x1] × [y0, y1] at height z0 from the
// reference point o. The solid angle is S = γ0 + γ1 + γ2 + γ3 - 2π, from the angles γi between the planes
// through o and consecutive edges. u0 picks the sub-rectangle [x0, xu] of solid angle u0 S (xu in closed
// form), u1 the height yv uniformly in h = y / √(xu² + z0² + y²), which makes the density uniform: 1 / S.
#pragma once

#include <optional>

#include "illum/math/vector.h"

namespace illum {

struct SphericalRectangleSample {
    Point3f p;
    float pdf = 0; // 1 / S, per steradian at o
};

// The solid angle of the rectangle (s, ex, ey) seen from o (0 when o lies in its plane).
float spherical_rectangle_solid_angle(Point3f o, Point3f s, Vector3f ex, Vector3f ey);

// A point of the rectangle uniformly distributed in the solid angle it subtends at o; nullopt when that
// solid angle is 0.
std::optional<SphericalRectangleSample> sample_spherical_rectangle(Point3f o, Point3f s, Vector3f ex,
                                                                   Vector3f ey, Point2f u);

// The u that sample_spherical_rectangle maps to the rectangle's point p.
Point2f invert_spherical_rectangle_sample(Point3f o, Point3f s, Vector3f ex, Vector3f ey, Point3f p);

} // namespace illum
