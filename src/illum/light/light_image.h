// The image a light reads from its "filename" (pbrt-v4's goniometric, projection and image area lights):
// read once at build, checked the way pbrt-v4 checks it, and looked up as pbrt-v4 looks it up.
#pragma once

#include <optional>
#include <string>

#include "illum/image/image.h"
#include "illum/math/vector.h"
#include "illum/param/entity.h"
#include "illum/util/diagnostics.h"

namespace illum {

// The image named by the string parameter `filename` of `e` (the parser has resolved it against the
// scene's folder). An unreadable or missing file is recorded in `diag` (so every missing file of a scene
// is reported together) and gives nullopt. Throws illum::Error at the parameter for an empty name and,
// as pbrt-v4 does ("image has infinite pixel values and so is not suitable as a light"), for a non-finite
// pixel. 8-bit files are sRGB-decoded to linear values, as pbrt-v4's image reader does; negative values
// (which pbrt-v4 clamps at every lookup) are set to zero once.
std::optional<Image> read_light_image(const EntityDesc& e, const std::string& what, Diagnostics& diag);

// pbrt-v4's Image::LookupNearest with its default clamp wrapping: the texel that contains image coordinates
// uv in [0, 1]² (u along a row from the left, v down the rows from the top).
inline const Color3& lookup_nearest(const Image& img, Point2f uv) {
    int x = std::clamp(int(uv.x * float(img.width())), 0, img.width() - 1);
    int y = std::clamp(int(uv.y * float(img.height())), 0, img.height() - 1);
    return img(x, y);
}

// pbrt-v4's Image::Bilerp with clamp wrapping: bilinear between texel centres, texel (x, y) centred at
// ((x + 1/2) / width, (y + 1/2) / height).
Color3 lookup_bilinear(const Image& img, Point2f uv);

} // namespace illum
