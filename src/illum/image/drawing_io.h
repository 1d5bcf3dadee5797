// Writing a Drawing by file name: .svg as SVG text (svg.h), .png rasterised (rasterize.h) through the
// PNG writer; both atomically (a temporary file renamed over the path).
#pragma once

#include <string>

#include "illum/image/drawing.h"

namespace illum {

// Throws illum::Error naming the file for another extension or a failed write.
void write_drawing(const Drawing& drawing, const std::string& path, float png_scale = 1);
// Whether write_drawing accepts the extension of `path`.
bool is_drawing_extension(const std::string& path);

} // namespace illum
