#include "illum/analysis/figure.h"

#include <cmath>

#include <fmt/format.h>

namespace illum {

std::vector<double> nice_ticks(double lo, double hi, int target) {
    std::vector<double> out;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
    double raw = (hi - lo) / std::max(1, target), mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
        out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
    return out;
}

std::string tick_label(double v) { return fmt::format("{:.4g}", v); }

void arrow(Drawing& d, Point2f from, Point2f to, Color3 colour, float width) {
    d.line(from, to, colour, width);
    Vector2f v = to - from;
    float len = std::sqrt(v.x * v.x + v.y * v.y);
    if (len < 1e-3f) return;
    Vector2f u = v * (1 / len), n(-u.y, u.x);
    float head = std::min(10.0f, 0.4f * len);
    d.add(Stroke{
        {to + (u * -head) + n * (0.45f * head), to, to + (u * -head) + n * (-0.45f * head)}, colour, width});
}

void Axes::draw(Drawing& d, const std::vector<double>& xticks, const std::vector<double>& yticks,
                const std::string& xlabel, const std::string& ylabel) const {
    for (double x : xticks) {
        Point2f a = map(x, y0), b = map(x, y1);
        d.line(a, b, palette::kGrid, 1);
        d.text({a.x, a.y + 16}, tick_label(x), 11, TextAnchor::Middle, palette::kInk);
    }
    for (double y : yticks) {
        Point2f a = map(x0, y), b = map(x1, y);
        d.line(a, b, palette::kGrid, 1);
        d.text({a.x - 6, a.y + 4}, tick_label(y), 11, TextAnchor::End, palette::kInk);
    }
    d.add(Stroke{{{left, top}, {left + width, top}, {left + width, top + height}, {left, top + height}},
                 palette::kInk,
                 1,
                 true});
    d.text({left + width / 2, top + height + 34}, xlabel, 12, TextAnchor::Middle, palette::kInk);
    d.text({left, top - 8}, ylabel, 12, TextAnchor::Start, palette::kInk);
}

} // namespace illum
