// Camera importance W_e (Veach 1997 §4.5; PBR 4th ed. §16.1.1): the camera as a sensor whose measurement
// of pixel j is I_j = ∫ W_e^(j)(p, ω) L(p, -ω) |cos θ| dA dω. Light tracing needs it to connect a vertex
// of a light path to the lens and splat its contribution onto the film.
//
// Normalisation (PBR 4th ed. eq. 16.3): for the perspective camera, W_e(p, ω) = 1 / (A_film A_lens cos⁴θ)
// inside the film's field of view and 0 outside, with A_film the film's area on the z = 1 plane of camera
// space and A_lens the lens area (π r², or 1 for a pinhole, whose lens point is a delta). Then
// ∫∫ W_e cos θ dω dA_lens = 1: a splat of value W_e L |cos| / p estimates the film's mean measurement, and
// the pixel's is that times the number of pixels (so the image is Σ splats / samples per pixel).
#pragma once

#include "illum/math/vector.h"
#include "illum/radiometry/quantity.h"

namespace illum {

// Importance per unit area and solid angle [m^-2 sr^-1] (of the normalised measurement).
using Importance = Scalar<0, -2, -1>;

// A lens point sampled as seen from a reference point: camera.sample_wi(p_ref, u).
struct CameraWiSample {
    Point3f p_lens;    // the point on the lens (the pinhole; on the film plane for orthographic)
    Normal3f n_lens;   // the camera's viewing direction (+z of camera space) in world space
    Vector3f wi;       // unit direction from the reference point towards p_lens
    Importance we;     // W_e along the ray from p_lens towards the reference point
    SolidAnglePdf pdf; // of wi at the reference point: p_A(lens) r² / |cos θ_lens|; 1 for a delta
    Point2f p_raster;  // where the ray lands on the film
};

// The pdfs with which generate_ray() makes a ray: of its origin per unit lens area, of its direction per
// steradian (PBR 4th ed. §16.1.1, PerspectiveCamera::PDF_We).
struct CameraRayPdf {
    AreaPdf pos;
    SolidAnglePdf dir;
};

} // namespace illum
