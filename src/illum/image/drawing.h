// A figure as a list of vector primitives in pixel coordinates (x to the right, y down, the origin at the
// top-left corner), painted in order. One description, two outputs: svg.h writes it as SVG text and
// rasterize.h paints it into an Image for PNG, so a plot's SVG and PNG show the same thing.
//
// Colours are display colours (sRGB-encoded, each channel in [0, 1]) as a plotting library or CSS takes
// them; the rasteriser blends in linear light after decoding them.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "illum/image/image.h"
#include "illum/math/vector.h"

namespace illum {

// A polyline; `closed` joins the last point to the first. dash > 0: dashes and gaps of that length.
struct Stroke {
    std::vector<Point2f> points;
    Color3 colour{0.0f};
    float width = 1;
    bool closed = false;
    float dash = 0;
};

// A filled polygon (even-odd rule), with an opacity in [0, 1].
struct Fill {
    std::vector<Point2f> points;
    Color3 colour{0.0f};
    float opacity = 1;
};

enum class TextAnchor { Start, Middle, End };

// One line of text whose baseline starts at (Start), is centred on (Middle) or ends at (End) `at`.
// UTF-8; the rasteriser's font has printable ASCII and the Greek letters and signs plots use.
struct Text {
    Point2f at;
    std::string text;
    float size = 12; // the height of a capital letter plus its descent, in pixels, as SVG's font-size
    Color3 colour{0.0f};
    TextAnchor anchor = TextAnchor::Start;
};

// An image shown in the rectangle [x, x + width] x [y, y + height]; its pixels are display colours
// (already exposed and tone mapped, not yet sRGB-encoded: linear display values in [0, 1]).
struct Picture {
    Image image;
    float x = 0, y = 0, width = 0, height = 0;
};

using DrawItem = std::variant<Stroke, Fill, Text, Picture>;

struct Drawing {
    int width = 0, height = 0;
    Color3 background{1.0f};
    std::vector<DrawItem> items;

    void add(DrawItem item) { items.push_back(std::move(item)); }
    void line(Point2f a, Point2f b, Color3 colour, float width = 1, float dash = 0) {
        add(Stroke{{a, b}, colour, width, false, dash});
    }
    void text(Point2f at, std::string s, float size, TextAnchor anchor = TextAnchor::Start,
              Color3 colour = Color3(0.0f)) {
        add(Text{at, std::move(s), size, colour, anchor});
    }
    void rectangle(float x, float y, float w, float h, Color3 colour, float opacity = 1) {
        add(Fill{{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, colour, opacity});
    }
};

} // namespace illum
