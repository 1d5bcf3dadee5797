// 8-bit display images: PNG writing (exposure, tone map, sRGB, quantisation) and reading of PNG, JPEG,
// TGA and BMP through stb_image, decoded from sRGB to linear.
#pragma once

#include <span>
#include <string>

#include "illum/image/image.h"
#include "illum/image/tonemap.h"

namespace illum {

// 8-bit RGB PNG of srgb8_encode(tonemap(2^exposure_stops * pixel)). Throws illum::Error for an empty image.
std::string encode_png(const Image& image, ToneMap tonemap = ToneMap::Clamp, float exposure_stops = 0.0f);

// Decodes any format stb_image reads (PNG, JPEG, TGA, BMP, ...) as sRGB-encoded colour and returns linear
// values (16-bit PNGs keep their precision). Greyscale becomes r = g = b; alpha is dropped.
// `name` is for error messages.
Image decode_ldr(std::span<const unsigned char> bytes, const std::string& name);

} // namespace illum
