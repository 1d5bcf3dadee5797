// Reading and writing images by file name, dispatching on the extension (case-insensitive).
#pragma once

#include <string>

#include "illum/image/exr.h"
#include "illum/image/image.h"
#include "illum/image/tonemap.h"

namespace illum {

// exposure_stops and tonemap apply to display formats (.png) only; .exr, .pfm and .hdr keep linear
// radiance unchanged. exr: the layout of .exr files (precision, crop window; exr.h).
struct WriteOptions {
    float exposure_stops = 0; // scale by 2^exposure_stops before tone mapping
    ToneMap tonemap = ToneMap::Clamp;
    ExrLayout exr;
};

// Reads .exr, .pfm, .hdr (linear) and .png, .jpg, .jpeg, .tga, .bmp (sRGB, decoded to linear).
// Throws illum::Error naming the file for a missing, unreadable, truncated or corrupt file, or an unknown
// extension.
Image read_image(const std::string& path);

// Writes .exr (RGB, 32-bit float unless opts.exr says half), .pfm (little-endian RGB), .hdr (RGBE) or .png
// (8-bit sRGB) atomically: the bytes go to a temporary file next to `path` that is then renamed over it, so
// an existing file is replaced whole or not at all. Throws illum::Error (`cannot write "path": reason`) on
// failure, including for an empty image or an unknown extension.
void write_image(const Image& image, const std::string& path, const WriteOptions& opts = {});

// Whether write_image / read_image accept the extension of `path` (for validating options early).
bool is_supported_output_extension(const std::string& path);
bool is_supported_input_extension(const std::string& path);

// The lower-case extension of the file name in `path`, with the dot (".exr"); empty if there is none.
std::string image_extension(const std::string& path);

} // namespace illum
