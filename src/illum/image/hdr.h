// Radiance RGBE (.hdr) images through stb_image / stb_image_write.
#pragma once

#include <span>
#include <string>

#include "illum/image/image.h"

namespace illum {

// Decodes a Radiance HDR file (`name` is for error messages). The scanline data is walked first so that a
// truncated file throws illum::Error (stb alone would return the missing pixels as black).
Image decode_hdr(std::span<const unsigned char> bytes, const std::string& name);

// Encodes run-length compressed RGBE. RGBE holds no negative, NaN or infinite values: negatives and NaN
// are written as 0, and values beyond the RGBE range (2^127, +inf included) as its largest value. Relative
// precision is about 2^-8 of the largest channel. Throws illum::Error for an empty image.
std::string encode_hdr(const Image& image);

} // namespace illum
