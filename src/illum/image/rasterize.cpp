#include "illum/image/rasterize.h"

#include <algorithm>
#include <cmath>

#include "illum/image/bitmap_font.h"
#include "illum/image/tonemap.h"

namespace illum {

namespace {

constexpr float kFontUnit = 0.1f; // one font cell, as a fraction of the font size

Color3 linear(Color3 display) {
    return {srgb_decode(display.r), srgb_decode(display.g), srgb_decode(display.b)};
}

// Coverage of one primitive, gathered as the maximum over its parts (so the joints of a polyline are
// not painted twice), then composited once.
class Canvas {
public:
    explicit Canvas(Image& image) : image_(image), coverage_(image.pixel_count(), 0.0f) {}
    int width() const { return image_.width(); }
    int height() const { return image_.height(); }

    void cover(int x, int y, float a) {
        if (x < 0 || y < 0 || x >= width() || y >= height() || !(a > 0)) return;
        std::size_t i = std::size_t(y) * std::size_t(width()) + std::size_t(x);
        if (coverage_[i] == 0) touched_.push_back(i);
        coverage_[i] = std::max(coverage_[i], std::min(a, 1.0f));
    }
    // Blends `colour` (linear) over the covered pixels and clears the coverage.
    void flush(Color3 colour, float opacity) {
        Color3* px = image_.data();
        for (std::size_t i : touched_) {
            float a = coverage_[i] * opacity;
            px[i] = px[i] * (1 - a) + colour * a;
            coverage_[i] = 0;
        }
        touched_.clear();
    }
    Image& image() { return image_; }

private:
    Image& image_;
    std::vector<float> coverage_;
    std::vector<std::size_t> touched_;
};

// A round-capped segment of half-width hw: coverage falls from 1 to 0 over the pixel around its edge.
void segment(Canvas& c, Point2f a, Point2f b, float hw) {
    int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - hw - 1)));
    int x1 = std::min(c.width() - 1, int(std::ceil(std::max(a.x, b.x) + hw + 1)));
    int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - hw - 1)));
    int y1 = std::min(c.height() - 1, int(std::ceil(std::max(a.y, b.y) + hw + 1)));
    Vector2f ab = b - a;
    float len2 = ab.x * ab.x + ab.y * ab.y;
    float thin = std::min(1.0f, 2 * hw); // lines thinner than a pixel are fainter, not narrower
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            Point2f p(x + 0.5f, y + 0.5f);
            Vector2f ap = p - a;
            float t = len2 > 0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / len2, 0.0f, 1.0f) : 0.0f;
            float dx = ap.x - t * ab.x, dy = ap.y - t * ab.y;
            float d = std::sqrt(dx * dx + dy * dy);
            c.cover(x, y, std::clamp(hw + 0.5f - d, 0.0f, 1.0f) * thin);
        }
}

// The polyline cut into dashes of length `dash` with gaps of the same length.
std::vector<std::pair<Point2f, Point2f>> pieces(const std::vector<Point2f>& p, bool closed, float dash) {
    std::vector<std::pair<Point2f, Point2f>> out;
    std::size_t n = p.size(), segments = closed ? n : n - 1;
    float phase = 0; // arc length modulo 2 dash
    for (std::size_t i = 0; i < segments; ++i) {
        Point2f a = p[i], b = p[(i + 1) % n];
        if (dash <= 0) {
            out.push_back({a, b});
            continue;
        }
        Vector2f d = b - a;
        float len = std::sqrt(d.x * d.x + d.y * d.y), s = 0;
        while (s < len) {
            float left = (phase < dash ? dash : 2 * dash) - phase, step = std::min(left, len - s);
            if (phase < dash) out.push_back({a + d * (s / len), a + d * ((s + step) / len)});
            s += step;
            phase = std::fmod(phase + step, 2 * dash);
        }
    }
    return out;
}

void paint(Canvas& c, const Stroke& s, float k) {
    if (s.points.size() < 2) return;
    std::vector<Point2f> p;
    for (Point2f q : s.points) p.push_back({q.x * k, q.y * k});
    for (auto [a, b] : pieces(p, s.closed, s.dash * k)) segment(c, a, b, 0.5f * s.width * k);
    c.flush(linear(s.colour), 1);
}

bool inside(const std::vector<Point2f>& p, float x, float y) {
    bool in = false;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
        if ((p[i].y > y) != (p[j].y > y) && x < p[j].x + (y - p[j].y) / (p[i].y - p[j].y) * (p[i].x - p[j].x))
            in = !in;
    return in;
}

void paint(Canvas& c, const Fill& f, float k) {
    if (f.points.size() < 3) return;
    std::vector<Point2f> p;
    float xmin = 1e30f, xmax = -1e30f, ymin = 1e30f, ymax = -1e30f;
    for (Point2f q : f.points) {
        p.push_back({q.x * k, q.y * k});
        xmin = std::min(xmin, p.back().x);
        xmax = std::max(xmax, p.back().x);
        ymin = std::min(ymin, p.back().y);
        ymax = std::max(ymax, p.back().y);
    }
    int x0 = std::max(0, int(std::floor(xmin))), x1 = std::min(c.width() - 1, int(std::ceil(xmax)));
    int y0 = std::max(0, int(std::floor(ymin))), y1 = std::min(c.height() - 1, int(std::ceil(ymax)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            int hits = 0;
            for (int sy = 0; sy < 4; ++sy)
                for (int sx = 0; sx < 4; ++sx) hits += inside(p, x + (sx + 0.5f) / 4, y + (sy + 0.5f) / 4);
            c.cover(x, y, hits / 16.0f);
        }
    c.flush(linear(f.colour), std::clamp(f.opacity, 0.0f, 1.0f));
}

void paint(Canvas& c, const Text& t, float k) {
    std::vector<char32_t> cps = decode_utf8(t.text);
    float unit = t.size * kFontUnit * k;
    float w = float(cps.size()) * kGlyphAdvance * unit - (cps.empty() ? 0 : unit);
    float x = t.at.x * k - (t.anchor == TextAnchor::Middle ? w / 2 : t.anchor == TextAnchor::End ? w : 0);
    float top = t.at.y * k - kGlyphCapRows * unit;
    for (char32_t cp : cps) {
        const Glyph& g = glyph(cp);
        int x0 = int(std::floor(x)), x1 = int(std::ceil(x + kGlyphColumns * unit));
        int y0 = int(std::floor(top)), y1 = int(std::ceil(top + kGlyphRows * unit));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px) {
                int ink = 0;
                for (int sy = 0; sy < 3; ++sy)
                    for (int sx = 0; sx < 3; ++sx) {
                        int col = int(std::floor((px + (sx + 0.5f) / 3 - x) / unit));
                        int row = int(std::floor((py + (sy + 0.5f) / 3 - top) / unit));
                        if (col >= 0 && col < kGlyphColumns && row >= 0 && row < kGlyphRows &&
                            (g.rows[row] >> (4 - col) & 1))
                            ++ink;
                    }
                c.cover(px, py, ink / 9.0f);
            }
        x += kGlyphAdvance * unit;
    }
    c.flush(linear(t.colour), 1);
}

Color3 bilinear(const Image& img, float u, float v) {
    float fx = std::clamp(u * img.width() - 0.5f, 0.0f, float(img.width() - 1));
    float fy = std::clamp(v * img.height() - 0.5f, 0.0f, float(img.height() - 1));
    int x0 = int(fx), y0 = int(fy), x1 = std::min(x0 + 1, img.width() - 1),
        y1 = std::min(y0 + 1, img.height() - 1);
    float tx = fx - x0, ty = fy - y0;
    return (img(x0, y0) * (1 - tx) + img(x1, y0) * tx) * (1 - ty) +
           (img(x0, y1) * (1 - tx) + img(x1, y1) * tx) * ty;
}

void paint(Canvas& c, const Picture& p, float k) {
    if (p.image.empty() || !(p.width > 0) || !(p.height > 0)) return;
    float x0 = p.x * k, y0 = p.y * k, w = p.width * k, h = p.height * k;
    Image& out = c.image();
    for (int y = std::max(0, int(std::floor(y0))); y < std::min(c.height(), int(std::ceil(y0 + h))); ++y)
        for (int x = std::max(0, int(std::floor(x0))); x < std::min(c.width(), int(std::ceil(x0 + w))); ++x) {
            float u = (x + 0.5f - x0) / w, v = (y + 0.5f - y0) / h;
            if (u < 0 || u > 1 || v < 0 || v > 1) continue;
            out(x, y) = bilinear(p.image, u, v);
        }
}

} // namespace

float text_width(const std::string& text, float size) {
    std::size_t n = decode_utf8(text).size();
    return n == 0 ? 0 : (float(n) * kGlyphAdvance - 1) * size * kFontUnit;
}

Image rasterize(const Drawing& d, float scale) {
    int w = std::max(1, int(std::lround(d.width * scale))),
        h = std::max(1, int(std::lround(d.height * scale)));
    Image image(w, h, linear(d.background));
    Canvas canvas(image);
    for (const DrawItem& item : d.items) std::visit([&](const auto& x) { paint(canvas, x, scale); }, item);
    return image;
}

} // namespace illum
