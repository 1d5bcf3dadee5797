// The film accumulates filter-weighted radiance samples per pixel (in double, so thousands of samples
// per pixel lose nothing) and resolves to an image of the mean radiance, L_pixel = Σ w_i L_i / Σ w_i
// (PBR 4th ed. §8.8). Each pixel is written by exactly one task at a time, so no synchronisation is
// needed; the sums start on a 128-byte boundary (util/line_aligned.h), so a 16-pixel tile's row (512
// bytes) shares no cache line with the next tile's where the width is a multiple of 4.
#pragma once

#include <span>
#include <vector>

#include "illum/image/image.h"
#include "illum/radiometry/quantity.h"
#include "illum/util/line_aligned.h"

namespace illum {

// The pixels a film keeps, [x0, x1) x [y0, y1) in the full image's raster (pbrt-v4's pixelBounds): the
// camera projects onto the full resolution, the output image holds these pixels only.
struct PixelBounds {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    static PixelBounds full(int width, int height) { return {0, 0, width, height}; }
};

// The pixels of `b` from `image`, whose raster is the full image's.
Image crop(const Image& image, const PixelBounds& b);

class Film {
public:
    Film(int width, int height)
        : width_(width), height_(height), sums_(std::size_t(width) * height * 4, 0.0) {}

    int width() const { return width_; }
    int height() const { return height_; }

    // l: the sample's value in the output colour space (the sensor's conversion of its radiance).
    void add_sample(int x, int y, Color3 l, float weight) {
        double* px = &sums_[(std::size_t(y) * width_ + x) * 4];
        for (int c = 0; c < 3; ++c) px[c] += double(l[c]) * weight;
        px[3] += weight;
    }
    // Pixel (x, y)'s sums: Σ w L as rgb, then Σ w.
    const double* pixel_sums(int x, int y) const { return &sums_[(std::size_t(y) * width_ + x) * 4]; }
    // The image of the mean radiance: its Color3 pixels hold W m^-2 sr^-1 (the output boundary, where the
    // unit leaves the type; EXR and PFM keep it linear).
    Image resolve() const;
    void clear() { std::fill(sums_.begin(), sums_.end(), 0.0); }
    // The raw sums, four doubles a pixel (Σ w L as rgb, then Σ w), for adding the films of several
    // processes.
    std::span<double> accumulators() { return sums_; }

private:
    int width_, height_;
    LineAlignedVector<double> sums_;
};

} // namespace illum
