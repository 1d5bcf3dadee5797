// Paints a Drawing (drawing.h) into an Image of linear display values, for PNG output through the image
// writers: strokes as round-capped segments with analytic anti-aliasing (coverage from the distance to
// the segment, one pixel of ramp), fills by 4 x 4 supersampled even-odd tests, text in the bitmap font
// (bitmap_font.h) supersampled 3 x 3, pictures resampled bilinearly. Colours are decoded from sRGB and
// blended in linear light; write the result with the default clamp tone map (encode_png) to get back
// the display colours.
#pragma once

#include "illum/image/drawing.h"

namespace illum {

// `scale` multiplies every coordinate (2 draws the figure at twice its size).
Image rasterize(const Drawing& drawing, float scale = 1);

// The width in pixels of text at a font size, as the rasteriser draws it (advance of 6 font units per
// code point, a unit being 0.1 of the font size).
float text_width(const std::string& text, float size);

} // namespace illum
