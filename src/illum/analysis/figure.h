// What the plots share: axes with ticks at round numbers, arrows, a palette. Built on the Drawing of
// image/drawing.h, so every figure comes out as SVG or PNG alike.
#pragma once

#include <string>
#include <vector>

#include "illum/image/drawing.h"

namespace illum {

namespace palette {
inline const Color3 kInk{0.1f, 0.1f, 0.1f}, kGrid{0.85f, 0.85f, 0.85f}, kMuted{0.45f, 0.45f, 0.45f},
    kLight{0.85f, 0.6f, 0.0f};
// One colour per plotted model (Okabe & Ito 2008's colour-blind-safe set).
inline const Color3 kSeries[] = {
    {0.0f, 0.447f, 0.698f}, {0.835f, 0.369f, 0.0f}, {0.0f, 0.620f, 0.451f}, {0.8f, 0.475f, 0.655f}};
inline const Color3 kRed{0.85f, 0.2f, 0.2f}, kGreen{0.2f, 0.65f, 0.2f}, kBlue{0.2f, 0.3f, 0.9f};
} // namespace palette

// About `target` ticks at 1, 2 or 5 times a power of ten covering [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target = 5);
// A tick value with up to four significant digits and no trailing zeros ("0.25", "1e-05").
std::string tick_label(double v);

// A line with an open arrowhead at `to`.
void arrow(Drawing& d, Point2f from, Point2f to, Color3 colour, float width = 1.5f);

// A rectangle of the drawing mapped to data coordinates [x0, x1] x [y0, y1] (y up).
struct Axes {
    float left = 0, top = 0, width = 0, height = 0;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;

    Point2f map(double x, double y) const {
        return {float(left + (x - x0) / (x1 - x0) * width),
                float(top + height - (y - y0) / (y1 - y0) * height)};
    }
    // Frame, grid lines and labelled ticks, axis titles.
    void draw(Drawing& d, const std::vector<double>& xticks, const std::vector<double>& yticks,
              const std::string& xlabel, const std::string& ylabel) const;
};

} // namespace illum
