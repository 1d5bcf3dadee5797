#include "illum/image/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "illum/image/ldr.h"

namespace illum {

namespace {

std::string hex_colour(Color3 c) {
    auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
    return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

// A coordinate with two decimals, finite (a NaN point would make the file invalid).
std::string num(float v) { return fmt::format("{:.2f}", std::isfinite(v) ? v : 0.0f); }

std::string points(const std::vector<Point2f>& p) {
    std::string out;
    for (const Point2f& q : p) {
        if (!out.empty()) out += ' ';
        out += num(q.x);
        out += ',';
        out += num(q.y);
    }
    return out;
}

void write(std::string& out, const Stroke& s) {
    if (s.points.size() < 2) return;
    out +=
        fmt::format("<{} points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
                    "stroke-linejoin=\"round\" stroke-linecap=\"round\"{}/>\n",
                    s.closed ? "polygon" : "polyline", points(s.points), hex_colour(s.colour), num(s.width),
                    s.dash > 0 ? fmt::format(" stroke-dasharray=\"{} {}\"", num(s.dash), num(s.dash)) : "");
}

void write(std::string& out, const Fill& f) {
    if (f.points.size() < 3) return;
    out += fmt::format("<polygon points=\"{}\" fill=\"{}\" fill-rule=\"evenodd\"{}/>\n", points(f.points),
                       hex_colour(f.colour),
                       f.opacity < 1 ? fmt::format(" fill-opacity=\"{}\"", num(f.opacity)) : "");
}

void write(std::string& out, const Text& t) {
    const char* anchor = t.anchor == TextAnchor::Start    ? "start"
                         : t.anchor == TextAnchor::Middle ? "middle"
                                                          : "end";
    out +=
        fmt::format("<text x=\"{}\" y=\"{}\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" "
                    "font-size=\"{}\" text-anchor=\"{}\" fill=\"{}\">{}</text>\n",
                    num(t.at.x), num(t.at.y), num(t.size), anchor, hex_colour(t.colour), xml_escape(t.text));
}

void write(std::string& out, const Picture& p) {
    if (p.image.empty()) return;
    std::string uri = "data:image/png;base64," + base64(encode_png(p.image));
    out += fmt::format("<image x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" preserveAspectRatio=\"none\" "
                       "xlink:href=\"{}\"/>\n",
                       num(p.x), num(p.y), num(p.width), num(p.height), uri);
}

} // namespace

std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint8_t(bytes[i + 2]);
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
    }
    return out;
}

std::string to_svg(const Drawing& d) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out +=
        fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
                    "version=\"1.1\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\">\n",
                    d.width, d.height, d.width, d.height);
    out += fmt::format("<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", d.width, d.height,
                       hex_colour(d.background));
    for (const DrawItem& item : d.items) std::visit([&](const auto& x) { write(out, x); }, item);
    out += "</svg>\n";
    return out;
}

} // namespace illum
