// A lens system's thick-lens approximation found by tracing, and focusing with it, as pbrt-v4's
// RealisticCamera does (PBR 4th ed. §5.3; cameras.cpp, ComputeThickLensApproximation, FocusThickLens).
//
// A ray parallel to the axis at a small height h, traced from the scene, leaves the rear surface and
// crosses the axis at the back focal point F'; it reaches height h again at the back principal plane P'.
// Traced from the film side, the same gives F and P in object space. The effective focal length is
// f = z(P') - z(F') (both sides are air). h is small enough for the paraxial limit (aberrations go as h²).
//
// Focusing moves the film: with the object at distance D from the film and the rear vertex moved by δ,
// the Gaussian lens formula 1/s_o + 1/s_i = 1/f with s_i = z(P') + δ and s_o = D - z(P) - δ gives, for
// T = s_o + s_i = D - z(P) + z(P'), s_i² - T s_i + T f = 0, so s_i = (T - sqrt(T (T - 4 f))) / 2 (the
// root near f; none when T < 4 f, an object too close to image).
#pragma once

#include <optional>

#include "illum/camera/lens_system.h"

namespace illum {

struct CardinalPoints {
    double focal_image = 0, principal_image = 0;   // z of F' and P' (film side)
    double focal_object = 0, principal_object = 0; // z of F and P (scene side)
    double efl() const { return principal_image - focal_image; }
};

// nullopt when a ray at that height is blocked (a stop closed to nothing).
std::optional<CardinalPoints> trace_cardinal_points(const LensSystem& lens, double lambda_nm, double height);
// A paraxial height for trace_cardinal_points: 1e-4 of the smallest aperture radius.
double paraxial_height(const LensSystem& lens);

// The film distance (the rear vertex's z) that focuses the plane at focus_distance from the film, given
// the cardinal points at the current film distance; nullopt when the plane is too close.
std::optional<double> thick_lens_film_distance(const LensSystem& lens, const CardinalPoints& cp,
                                               double focus_distance);

} // namespace illum
