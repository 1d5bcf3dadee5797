// Image: a width x height grid of linear RGB (Color3), stored row-major from the top-left pixel.
#pragma once

#include <cstddef>
#include <vector>

#include "illum/radiometry/color.h"

namespace illum {

class Image {
public:
    Image() = default;
    // Throws illum::Error if a size is negative or the pixel count does not fit in memory indexing.
    Image(int width, int height, Color3 fill = Color3(0.0f));

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixel_count() const { return pixels_.size(); }
    bool empty() const { return pixels_.empty(); }

    // Bounds-checked access; throws std::out_of_range outside the image (a programming error).
    Color3& at(int x, int y);
    const Color3& at(int x, int y) const;
    // Unchecked access.
    Color3& operator()(int x, int y) { return pixels_[index(x, y)]; }
    const Color3& operator()(int x, int y) const { return pixels_[index(x, y)]; }

    Color3* data() { return pixels_.data(); }
    const Color3* data() const { return pixels_.data(); }

    // Changes the size; every pixel (old ones included) becomes `fill`.
    void resize(int width, int height, Color3 fill = Color3(0.0f));
    void fill(Color3 value);

    // Mean of each channel over all pixels, summed in double. Black for an empty image.
    Color3 channel_mean() const;
    // True if any component of any pixel is NaN or infinite.
    bool has_non_finite() const;

    bool operator==(const Image&) const = default;

private:
    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width_) + std::size_t(x); }

    int width_ = 0, height_ = 0;
    std::vector<Color3> pixels_;
};

} // namespace illum
