// The camera, film and pixel filter of a scene file (pbrt-v4's Camera, Film and PixelFilter directives),
// each read from its own parameters.
#pragma once

#include <memory>
#include <string>

#include "illum/camera/camera.h"
#include "illum/camera/film.h"
#include "illum/camera/filter.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

struct FilmSettings {
    int width = 1280, height = 720;
    std::string filename;                      // "" when the film names none
    float diagonal_mm = 35;                    // the sensor's diagonal, for the realistic camera
    PixelBounds pixel_bounds{0, 0, 1280, 720}; // the pixels the output keeps
    bool save_fp16 = true;                     // EXR output in half precision (pbrt-v4's default)
};

// "rgb" (and "gbuffer", "spectral", rendered as rgb with a warning): xresolution, yresolution, filename,
// diagonal, savefp16, and the pixels kept: "cropwindow" [x0 x1 y0 y1] in [0, 1] (NDC, y down), becoming
// pixels [ceil(W x0), ceil(W x1)) x [ceil(H y0), ceil(H y1)) as pbrt-v4 rounds, or "pixelbounds"
// [x0 x1 y0 y1] in pixels; the crop window wins when both are given, as in pbrt-v4. Both accept their
// pairs in either order, as pbrt-v4 does; a window outside [0, 1] or bounds outside the image are errors
// (pbrt-v4 clamps them), and so is one that keeps no pixel. maxcomponentvalue belongs to the sensor
// (create_sensor.h).
FilmSettings create_film(const EntityDesc& film, Diagnostics& diag);
// "box", "triangle", "gaussian" (xradius, yradius, sigma), "mitchell" (B, C) and "sinc" (tau).
std::unique_ptr<Filter> create_filter(const EntityDesc& filter, Diagnostics& diag);
// "perspective" (fov, lensradius, focaldistance, frameaspectratio, screenwindow), "orthographic" and
// "realistic" (lensfile, aperturediameter, focusdistance, aperture; realistic_camera.h) and "spherical"
// (mapping; spherical_camera.h). A lens or aperture file that cannot be read is recorded in diag (and a
// stand-in camera returned), so the build reports it with every other missing file.
std::unique_ptr<Camera> create_camera(const CameraDesc& camera, const FilmSettings& film, Diagnostics& diag);

} // namespace illum
