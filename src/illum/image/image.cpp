#include "illum/image/image.h"

#include <stdexcept>
#include <string>

#include "illum/util/error.h"

namespace illum {

Image::Image(int width, int height, Color3 fill) { resize(width, height, fill); }

void Image::resize(int width, int height, Color3 fill) {
    if (width < 0 || height < 0)
        throw Error("invalid image size " + std::to_string(width) + "x" + std::to_string(height));
    width_ = width;
    height_ = height;
    pixels_.assign(std::size_t(width) * std::size_t(height), fill);
}

void Image::fill(Color3 value) { pixels_.assign(pixels_.size(), value); }

Color3& Image::at(int x, int y) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_)
        throw std::out_of_range("Image::at(" + std::to_string(x) + ", " + std::to_string(y) + ") outside " +
                                std::to_string(width_) + "x" + std::to_string(height_));
    return pixels_[index(x, y)];
}

const Color3& Image::at(int x, int y) const { return const_cast<Image*>(this)->at(x, y); }

Color3 Image::channel_mean() const {
    if (pixels_.empty()) return Color3(0.0f);
    double sum[3] = {0, 0, 0};
    for (const Color3& c : pixels_) {
        sum[0] += c.r;
        sum[1] += c.g;
        sum[2] += c.b;
    }
    const double n = double(pixels_.size());
    return {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

bool Image::has_non_finite() const {
    for (const Color3& c : pixels_)
        if (!c.is_finite()) return true;
    return false;
}

} // namespace illum
