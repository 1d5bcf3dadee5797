#include "illum/light/light_image.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/image/image_io.h"

namespace illum {

std::optional<Image> read_light_image(const EntityDesc& e, const std::string& what, Diagnostics& diag) {
    const Param* f = e.params.find("filename");
    std::string path = e.params.get_string("filename", "");
    if (!f || path.empty())
        throw Error(f ? f->loc : e.loc, fmt::format("{} needs \"string filename\"", what));
    Image img;
    try {
        img = read_image(path);
    } catch (const Error& err) {
        diag.missing_file(f->loc, err.what());
        return std::nullopt;
    }
    if (img.empty()) throw Error(f->loc, fmt::format("{}: image \"{}\" is empty", what, path));
    if (img.has_non_finite())
        throw Error(f->loc,
                    fmt::format("{}: image \"{}\" has infinite or not-a-number pixel values and so is "
                                "not suitable as a light",
                                what, path));
    for (std::size_t i = 0; i < img.pixel_count(); ++i) {
        Color3& c = img.data()[i];
        for (int k = 0; k < 3; ++k) c[k] = std::max(c[k], 0.0f);
    }
    return img;
}

Color3 lookup_bilinear(const Image& img, Point2f uv) {
    float x = uv.x * float(img.width()) - 0.5f, y = uv.y * float(img.height()) - 0.5f;
    float fx = std::floor(x), fy = std::floor(y);
    float dx = x - fx, dy = y - fy;
    int x0 = int(fx), y0 = int(fy);
    auto at = [&](int xi, int yi) -> const Color3& {
        return img(std::clamp(xi, 0, img.width() - 1), std::clamp(yi, 0, img.height() - 1));
    };
    return at(x0, y0) * ((1 - dx) * (1 - dy)) + at(x0 + 1, y0) * (dx * (1 - dy)) +
           at(x0, y0 + 1) * ((1 - dx) * dy) + at(x0 + 1, y0 + 1) * (dx * dy);
}

} // namespace illum
