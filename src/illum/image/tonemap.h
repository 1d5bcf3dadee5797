// Display transforms: exposure, tone mapping of linear radiance to [0, 1], and the sRGB transfer curve.
#pragma once

#include <optional>
#include <string_view>

#include "illum/image/image.h"

namespace illum {

enum class ToneMap {
    Clamp,    // min(max(x, 0), 1)
    Reinhard, // x / (1 + x) on each channel
    Aces,     // Narkowicz's fit of the ACES filmic curve
};

// "clamp", "reinhard" or "aces" (case-insensitive); nullopt for anything else.
std::optional<ToneMap> tonemap_from_string(std::string_view name);
const char* to_string(ToneMap t);

// Maps one linear value (after exposure) to [0, 1]. NaN maps to 0, +inf to 1, negatives to 0.
float tonemap(float x, ToneMap t);
// Applies 2^exposure_stops, then the tone map, channel by channel. The result is display-linear in
// [0, 1], not yet sRGB-encoded.
Color3 tonemap(Color3 c, ToneMap t, float exposure_stops = 0.0f);
Image tonemapped(const Image& image, ToneMap t, float exposure_stops = 0.0f);

// The sRGB transfer functions of IEC 61966-2-1 (exact piecewise form, not a 2.2 power):
//   encode(x) = 12.92 x                   for x <= 0.0031308
//             = 1.055 x^(1/2.4) - 0.055   otherwise
//   decode(v) = v / 12.92                 for v <= 0.04045
//             = ((v + 0.055) / 1.055)^2.4 otherwise
// Inputs are clamped to [0, 1] (NaN gives 0).
float srgb_encode(float linear);
float srgb_decode(float encoded);
// Decodes an 8-bit sRGB code value through a table built once from srgb_decode.
float srgb8_decode(unsigned char code);
// round(255 * srgb_encode(x)).
unsigned char srgb8_encode(float linear);

} // namespace illum
