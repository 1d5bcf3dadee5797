// The film accumulates filter-weighted radiance samples per pixel (in double, so thousands of samples
// per pixel lose nothing) and resolves to an image of the mean radiance, L_pixel = Σ w_i L_i / Σ w_i
// (PBR 4th ed. §8.8). Each pixel is written by exactly one task at a time, so no synchronisation is
// needed.
#pragma once

#include <vector>

#include "illum/image/image.h"
#include "illum/radiometry/quantity.h"

namespace illum {

class Film {
public:
    Film(int width, int height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

    int width() const { return width_; }
    int height() const { return height_; }

    // l: the sample's value in the output colour space (the sensor's conversion of its radiance).
    void add_sample(int x, int y, Color3 l, float weight) {
        Pixel& px = pixels_[std::size_t(y) * width_ + x];
        for (int c = 0; c < 3; ++c) px.sum[c] += double(l[c]) * weight;
        px.weight += weight;
    }
    // The image of the mean radiance: its Color3 pixels hold W m^-2 sr^-1 (the output boundary, where the
    // unit leaves the type; EXR and PFM keep it linear).
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
