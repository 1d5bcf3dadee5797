// Shapes of the aperture stop for pbrt-v4's realistic camera ("string aperture"): its built-in
// "gaussian", "square", "pentagon" and "star", and an image file. Each is a transmission over the stop's
// bounding square, (u, v) in [-1, 1]² (the stop point over the stop radius), scaled so that its integral
// over the square is π, that of the default circular stop: changing the shape changes the bokeh, not the
// exposure (pbrt-v4 cameras.cpp, RealisticCamera::Create, normalises its images the same way).
//
// pbrt-v4 rasterises the built-in shapes into 256² images that it looks up bilinearly; here they are
// evaluated exactly (sharp edges, the same shapes and scale). Its images are flipped in y before the look-
// up, so the pentagon's apex points to -v, as here, and an image file's top row lies at +v (camera +y).
#pragma once

#include <memory>
#include <string>

#include "illum/camera/lens_system.h"
#include "illum/image/image.h"

namespace illum {

// nullptr for a name that is not built in ("" and "circular" are the default stop, also nullptr).
std::shared_ptr<const ApertureShape> builtin_aperture(const std::string& name);
bool is_builtin_aperture(const std::string& name);
// An image's mean of R, G, B looked up bilinearly (black outside), scaled as above. Throws illum::Error
// for an empty or black image.
std::shared_ptr<const ApertureShape> image_aperture(const Image& image);

} // namespace illum
