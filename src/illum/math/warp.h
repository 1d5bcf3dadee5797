// Warps: maps from the unit square to sampling domains, each with its pdf with respect to the
// domain's measure (area for the disk and triangle, solid angle for directions).
#pragma once

#include <array>

#include "illum/math/vector.h"

namespace illum {

// Concentric map of the square onto the unit disk (Shirley & Chiu 1997). pdf = 1/π per unit area.
Point2f sample_uniform_disk_concentric(Point2f u);
// Polar map onto the unit disk. pdf = 1/π.
Point2f sample_uniform_disk_polar(Point2f u);
constexpr float uniform_disk_pdf() { return kInvPi; }

// Uniform over the hemisphere z >= 0. pdf = 1/(2π) sr^-1.
Vector3f sample_uniform_hemisphere(Point2f u);
constexpr float uniform_hemisphere_pdf() { return 0.5f * kInvPi; }

// Cosine-weighted over z >= 0 via Malley's method. pdf = cos θ / π.
Vector3f sample_cosine_hemisphere(Point2f u);
inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta > 0 ? cos_theta * kInvPi : 0.0f; }

// Uniform over the unit sphere. pdf = 1/(4π).
Vector3f sample_uniform_sphere(Point2f u);
constexpr float uniform_sphere_pdf() { return kInv4Pi; }

// Uniform over the cone of directions around +z with cos θ >= cos_theta_max. pdf = 1/(2π(1 - cos θmax)).
Vector3f sample_uniform_cone(Point2f u, float cos_theta_max);
inline float uniform_cone_pdf(float cos_theta_max) { return 1.0f / (2 * kPi * (1 - cos_theta_max)); }

// Uniform over a triangle: barycentrics (b0, b1, b2) by the low-distortion square-to-triangle map
// (Heitz 2019, "A Low-Distortion Map Between Triangle and Square"). pdf = 1/area.
std::array<float, 3> sample_uniform_triangle(Point2f u);

// Uniform by solid angle over the spherical triangle that triangle (v0, v1, v2) subtends from p
// (Arvo 1995, "Stratified Sampling of Spherical Triangles"). Returns barycentrics of the point on the
// triangle and sets *pdf (per steradian); pdf 0 when the triangle is degenerate as seen from p.
std::array<float, 3> sample_spherical_triangle(const std::array<Point3f, 3>& v, Point3f p, Point2f u,
                                               float* pdf);
// The solid angle of the spherical triangle with unit vertices a, b, c (Van Oosterom & Strackee 1983).
float spherical_triangle_area(Vector3f a, Vector3f b, Vector3f c);
// The density 1/Ω of sample_spherical_triangle, computed exactly as the sampler does (the two agree to
// the bit); 0 when the triangle is degenerate as seen from p.
float spherical_triangle_pdf(const std::array<Point3f, 3>& v, Point3f p);

} // namespace illum
