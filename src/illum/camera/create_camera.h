// The camera, film and pixel filter of a scene file (pbrt-v4's Camera, Film and PixelFilter directives),
// each read from its own parameters.
#pragma once

#include <memory>
#include <string>

#include "illum/camera/camera.h"
#include "illum/camera/filter.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

struct FilmSettings {
    int width = 1280, height = 720;
    std::string filename;   // "" when the film names none
    float diagonal_mm = 35; // the sensor's diagonal, for the realistic camera
};

// "rgb" (and "gbuffer", "spectral", rendered as rgb with a warning): xresolution, yresolution, filename,
// diagonal.
FilmSettings create_film(const EntityDesc& film, Diagnostics& diag);
// "box", "triangle", "gaussian" (xradius, yradius, sigma), "mitchell" (B, C) and "sinc" (tau).
std::unique_ptr<Filter> create_filter(const EntityDesc& filter, Diagnostics& diag);
// "perspective" (fov, lensradius, focaldistance, frameaspectratio, screenwindow), "orthographic" and
// "realistic" (lensfile, aperturediameter, focusdistance, aperture; realistic_camera.h); "spherical" as a
// perspective camera, warned. A lens or aperture file that cannot be read is recorded in diag (and a
// stand-in camera returned), so the build reports it with every other missing file.
std::unique_ptr<Camera> create_camera(const CameraDesc& camera, const FilmSettings& film, Diagnostics& diag);

} // namespace illum
