// SVG 1.1 text of a Drawing (drawing.h), written by illum itself: polylines and polygons, text in a
// sans-serif font, pictures embedded as base64 PNG data URIs (RFC 2397, RFC 4648). Coordinates are written
// with two decimals, so the text is short and does not depend on the platform's float formatting.
#pragma once

#include <string>

#include "illum/image/drawing.h"

namespace illum {

std::string to_svg(const Drawing& drawing);

// The text with &, <, >, " and ' written as XML entities.
std::string xml_escape(const std::string& text);
// RFC 4648 base64 with padding.
std::string base64(const std::string& bytes);

} // namespace illum
