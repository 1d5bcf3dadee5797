#include "illum/image/hdr.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "illum/util/error.h"

namespace illum {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

enum class Scan { Complete, Truncated, Corrupt };

// Walks the pixel data the way stb's decoder will (Radiance "new" run-length scanlines, falling back to
// flat RGBE for the rest of the image at the first scanline without the 2, 2 marker) and reports whether
// the file holds all of it. stb is only run on files that pass: Debian's stb_image loops forever on a
// zero-length literal run, and returns the pixels of a truncated file as black instead of failing.
Scan scan_rgbe(std::span<const unsigned char> b) {
    std::size_t pos = 0;
    auto next_line = [&](std::string& line) {
        line.clear();
        while (pos < b.size() && b[pos] != '\n') line.push_back(char(b[pos++]));
        if (pos >= b.size()) return false;
        ++pos;
        return true;
    };
    std::string line;
    if (!next_line(line) || line.rfind("#?", 0) != 0) return Scan::Corrupt;
    do {
        if (!next_line(line)) return Scan::Truncated;
    } while (!line.empty());
    if (!next_line(line)) return Scan::Truncated;
    int h = 0, w = 0;
    // stb reads only this orientation (top to bottom, left to right).
    if (std::sscanf(line.c_str(), "-Y %d +X %d", &h, &w) != 2 || w <= 0 || h <= 0) return Scan::Corrupt;

    const std::size_t flat_row = 4 * std::size_t(w);
    for (int y = 0; y < h; ++y) {
        // Flat data: stb then reads the whole image (all h rows, from pixel 0 again) from this position on,
        // even when earlier scanlines were run-length encoded.
        const Scan flat = b.size() - pos >= flat_row * std::size_t(h) ? Scan::Complete : Scan::Truncated;
        if (w < 8 || w >= 32768) return flat;
        if (b.size() - pos < 4) return Scan::Truncated;
        if (b[pos] != 2 || b[pos + 1] != 2 || (b[pos + 2] & 0x80)) return flat;
        pos += 4;
        for (int c = 0; c < 4; ++c)
            for (int x = 0; x < w;) {
                if (pos >= b.size()) return Scan::Truncated;
                int count = b[pos++];
                std::size_t literal = std::size_t(count);
                if (count > 128) { // a run: one value repeated count - 128 times
                    count -= 128;
                    literal = 1;
                }
                if (count == 0 || count > w - x) return Scan::Corrupt;
                if (b.size() - pos < literal) return Scan::Truncated;
                pos += literal;
                x += count;
            }
    }
    return Scan::Complete;
}

// The largest value RGBE holds: exponent byte 255 (2^127) with mantissa 255/256. Anything at or above
// 2^127 would overflow stb's exponent byte and wrap to black.
const float kMaxRgbe = std::ldexp(255.0f / 256.0f, 127);

void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

} // namespace

Image decode_hdr(std::span<const unsigned char> bytes, const std::string& name) {
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        throw Error(quoted(name) + " is too large");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int len = int(bytes.size());
    if (!stbi_is_hdr_from_memory(data, len)) throw Error(quoted(name) + " is not a Radiance HDR file");
    switch (scan_rgbe(bytes)) {
    case Scan::Truncated:
        throw Error(quoted(name) + " is truncated");
    case Scan::Corrupt:
        throw Error(quoted(name) +
                    " is corrupt or unsupported (bad header, resolution line or run-length data)");
    case Scan::Complete:
        break;
    }
    int w = 0, h = 0, n = 0;
    std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf_from_memory(data, len, &w, &h, &n, 3),
                                                   stbi_image_free);
    if (!pixels) throw Error("cannot read " + quoted(name) + ": " + stbi_failure_reason());
    Image image(w, h);
    const float* p = pixels.get();
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        image.data()[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    return image;
}

std::string encode_hdr(const Image& image) {
    if (image.empty()) throw Error("cannot encode an empty image as Radiance HDR");
    std::vector<float> rgb(3 * image.pixel_count());
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = image.data()[i][c];
            rgb[3 * i + c] = std::isnan(v) || v < 0 ? 0.0f : std::min(v, kMaxRgbe);
        }
    std::string out;
    if (!stbi_write_hdr_to_func(append, &out, image.width(), image.height(), 3, rgb.data()))
        throw Error("stb_image_write failed to encode Radiance HDR");
    return out;
}

} // namespace illum
