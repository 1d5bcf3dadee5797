// The film accumulates filter-weighted radiance samples per pixel (in double, so thousands of samples
// per pixel lose nothing) and resolves to an image of the mean. Each pixel is written by exactly one
// task at a time, so no synchronisation is needed.
#pragma once

#include <vector>

#include "illum/image/image.h"
#include "illum/radiometry/color.h"

namespace illum {

class Film {
public:
    Film(int width, int height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

    int width() const { return width_; }
    int height() const { return height_; }

    void add_sample(int x, int y, Color3 value, float weight) {
        Pixel& px = pixels_[std::size_t(y) * width_ + x];
        px.sum[0] += double(value.r) * weight;
        px.sum[1] += double(value.g) * weight;
        px.sum[2] += double(value.b) * weight;
        px.weight += weight;
    }
    Image resolve() const;
    void clear() { std::fill(pixels_.begin(), pixels_.end(), Pixel{}); }

private:
    struct Pixel {
        double sum[3] = {0, 0, 0};
        double weight = 0;
    };
    int width_, height_;
    std::vector<Pixel> pixels_;
};

} // namespace illum
