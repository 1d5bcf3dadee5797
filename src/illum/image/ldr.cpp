#include "illum/image/ldr.h"

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

void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

} // namespace

std::string encode_png(const Image& image, ToneMap tonemap_op, float exposure_stops) {
    if (image.empty()) throw Error("cannot encode an empty image as PNG");
    std::vector<unsigned char> rgb(3 * image.pixel_count());
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        const Color3 c = tonemap(image.data()[i], tonemap_op, exposure_stops);
        rgb[3 * i] = srgb8_encode(c.r);
        rgb[3 * i + 1] = srgb8_encode(c.g);
        rgb[3 * i + 2] = srgb8_encode(c.b);
    }
    std::string out;
    if (!stbi_write_png_to_func(append, &out, image.width(), image.height(), 3, rgb.data(),
                                3 * image.width()))
        throw Error("stb_image_write failed to encode PNG");
    return out;
}

Image decode_ldr(std::span<const unsigned char> bytes, const std::string& name) {
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        throw Error(quoted(name) + " is too large");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int len = int(bytes.size());
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_memory(data, len, &w, &h, &n))
        throw Error("cannot read " + quoted(name) + ": " + stbi_failure_reason());
    if (stbi_is_16_bit_from_memory(data, len)) {
        std::unique_ptr<stbi_us, void (*)(void*)> p(stbi_load_16_from_memory(data, len, &w, &h, &n, 3),
                                                    stbi_image_free);
        if (!p) throw Error("cannot read " + quoted(name) + ": " + stbi_failure_reason());
        Image image(w, h);
        for (std::size_t i = 0; i < image.pixel_count(); ++i)
            image.data()[i] = {srgb_decode(p.get()[3 * i] / 65535.0f),
                               srgb_decode(p.get()[3 * i + 1] / 65535.0f),
                               srgb_decode(p.get()[3 * i + 2] / 65535.0f)};
        return image;
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> p(stbi_load_from_memory(data, len, &w, &h, &n, 3),
                                                stbi_image_free);
    if (!p) throw Error("cannot read " + quoted(name) + ": " + stbi_failure_reason());
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        image.data()[i] = {srgb8_decode(p.get()[3 * i]), srgb8_decode(p.get()[3 * i + 1]),
                           srgb8_decode(p.get()[3 * i + 2])};
    return image;
}

} // namespace illum
