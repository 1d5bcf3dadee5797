// Portable float map (PFM): "PF" (RGB) or "Pf" (greyscale), then width, height and a scale whose sign
// gives the byte order (negative = little-endian, positive = big-endian), then 32-bit IEEE floats with
// rows stored bottom to top. As in pbrt, a scale magnitude other than 1 multiplies the values on reading.
#pragma once

#include <span>
#include <string>

#include "illum/image/image.h"

namespace illum {

// `name` is the file name used in error messages. Greyscale files are read into r = g = b.
// Throws illum::Error for a bad header or truncated data.
Image decode_pfm(std::span<const unsigned char> bytes, const std::string& name);
// Little-endian RGB ("PF", scale -1).
std::string encode_pfm(const Image& image);
// Greyscale ("Pf", scale -1) from each pixel's red channel; for images known to be grey.
std::string encode_pfm_grey(const Image& image);

} // namespace illum
