#include "illum/image/pfm.h"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "illum/util/error.h"

namespace illum {

namespace {

constexpr long kMaxDimension = 1 << 20;

struct Cursor {
    std::span<const unsigned char> bytes;
    std::size_t pos = 0;
    const std::string& name;

    [[noreturn]] void fail(const std::string& what) const {
        throw Error("\"" + name + "\" is not a valid PFM file: " + what);
    }
    void skip_space() {
        while (pos < bytes.size() && std::isspace(bytes[pos])) ++pos;
    }
    // The next whitespace-delimited token of the header.
    std::string token(const char* what) {
        skip_space();
        std::size_t start = pos;
        while (pos < bytes.size() && !std::isspace(bytes[pos]) && pos - start < 64) ++pos;
        if (start == pos) fail(std::string("missing ") + what);
        return std::string(reinterpret_cast<const char*>(bytes.data() + start), pos - start);
    }
    long integer(const char* what) {
        std::string t = token(what);
        char* end = nullptr;
        long v = std::strtol(t.c_str(), &end, 10);
        if (*end != '\0' || v <= 0 || v > kMaxDimension) fail(std::string("bad ") + what + " \"" + t + "\"");
        return v;
    }
};

float read_float(const unsigned char* p, bool little_endian) {
    std::uint32_t u;
    std::memcpy(&u, p, 4);
    if (little_endian != (std::endian::native == std::endian::little))
        u = (u >> 24) | ((u >> 8) & 0xff00u) | ((u << 8) & 0xff0000u) | (u << 24);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

void append_le(std::string& out, float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    for (int i = 0; i < 4; ++i) out.push_back(char((u >> (8 * i)) & 0xff));
}

std::string encode(const Image& image, bool grey) {
    std::string out = std::string(grey ? "Pf" : "PF") + "\n" + std::to_string(image.width()) + " " +
                      std::to_string(image.height()) + "\n-1.0\n";
    out.reserve(out.size() + image.pixel_count() * (grey ? 4 : 12));
    for (int y = image.height() - 1; y >= 0; --y)
        for (int x = 0; x < image.width(); ++x) {
            const Color3& c = image(x, y);
            append_le(out, c.r);
            if (!grey) {
                append_le(out, c.g);
                append_le(out, c.b);
            }
        }
    return out;
}

} // namespace

Image decode_pfm(std::span<const unsigned char> bytes, const std::string& name) {
    Cursor in{bytes, 0, name};
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f'))
        throw Error("\"" + name + "\" is not a PFM file (it does not start with PF or Pf)");
    const int channels = bytes[1] == 'F' ? 3 : 1;
    in.pos = 2;
    const long width = in.integer("width");
    const long height = in.integer("height");
    const std::string scale_text = in.token("scale");
    char* end = nullptr;
    const double scale = std::strtod(scale_text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(scale) || scale == 0) in.fail("bad scale \"" + scale_text + "\"");
    // Exactly one whitespace character separates the header from the data.
    if (in.pos >= bytes.size() || !std::isspace(bytes[in.pos])) in.fail("truncated header");
    ++in.pos;
    const bool little_endian = scale < 0;
    const float magnitude = float(std::abs(scale));

    const std::size_t needed = std::size_t(width) * std::size_t(height) * std::size_t(channels) * 4;
    const std::size_t available = bytes.size() - in.pos;
    if (available < needed)
        in.fail("truncated data (" + std::to_string(available) + " of " + std::to_string(needed) +
                " bytes for " + std::to_string(width) + "x" + std::to_string(height) + ")");

    Image image(static_cast<int>(width), static_cast<int>(height));
    const unsigned char* p = bytes.data() + in.pos;
    for (long row = 0; row < height; ++row) {
        const int y = int(height - 1 - row); // bottom row first
        for (int x = 0; x < int(width); ++x) {
            Color3& c = image(x, y);
            if (channels == 3) {
                c = {read_float(p, little_endian), read_float(p + 4, little_endian),
                     read_float(p + 8, little_endian)};
            } else {
                c = Color3(read_float(p, little_endian));
            }
            if (magnitude != 1.0f) c *= magnitude;
            p += 4 * channels;
        }
    }
    return image;
}

std::string encode_pfm(const Image& image) { return encode(image, false); }
std::string encode_pfm_grey(const Image& image) { return encode(image, true); }

} // namespace illum
