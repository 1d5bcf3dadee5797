// OpenEXR reading and writing through the OpenEXR 3 C++ API.
#pragma once

#include <span>
#include <string>

#include "illum/image/image.h"

namespace illum {

// Reads the first part of an OpenEXR file: R, G, B channels (half, float or uint; a missing one of the
// three reads as 0), a Y-only (greyscale) image, luminance/chroma (Y, RY, BY) images, or any single-channel
// image. Other channels (A, AOVs) are ignored. The result covers the display window; pixels outside the
// data window are black. `name` is the file name for error messages.
// Throws illum::Error for a file that is not OpenEXR, is truncated, or has no usable channels.
Image decode_exr(std::span<const unsigned char> bytes, const std::string& name);

// How an image is laid out in the file.
struct ExrLayout {
    // 16-bit half channels (values rounded to the nearest half, those above 65504, the largest finite
    // half, clamped to it, as pbrt-v4 writes its films) instead of 32-bit float.
    bool half = false;
    // The image is the window of a larger one (a cropped render): the file's display window is
    // display_width x display_height and its data window starts at (x0, y0), as pbrt-v4 writes a crop.
    // 0: the image is the whole display window.
    int display_width = 0, display_height = 0;
    int x0 = 0, y0 = 0;
};

// Encodes R, G, B channels, ZIP-compressed (lossless), Rec. 709 primaries (the default).
// Throws illum::Error for an empty image or a data window outside the display window.
std::string encode_exr(const Image& image, const ExrLayout& layout = {});

} // namespace illum
