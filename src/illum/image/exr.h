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

// Encodes 32-bit float R, G, B channels, ZIP-compressed (lossless), Rec. 709 primaries (the default).
// Throws illum::Error for an empty image.
std::string encode_exr(const Image& image);

} // namespace illum
