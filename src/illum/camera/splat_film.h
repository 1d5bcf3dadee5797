// The film of light tracing: contributions arrive at arbitrary raster positions and are splatted onto
// the pixels whose filter covers them, each weighted by the filter's value there (PBR 4th ed. §16.3,
// as pbrt-v4's RGBFilm::AddSplat). With N particles per pixel, pixel j's value is
//   I_j = Σ_splats f(p_j - p_splat) L_splat / (N ∫ f),
// the filter-weighted mean of the splats' estimates of the measurement (camera_importance.h: a splat's
// W_e is normalised to the whole film, so the pixel's share is that times the pixel count, which is
// what dividing by N rather than N · pixels does). Sums are in double; a SplatFilm is written by one
// thread at a time (light tracing applies its splats in a fixed order).
#pragma once

#include <span>
#include <vector>

#include "illum/camera/filter.h"
#include "illum/image/image.h"
#include "illum/math/vector.h"
#include "illum/radiometry/color.h"

namespace illum {

// One contribution, already in the output colour space.
struct Splat {
    Point2f p_raster;
    Color3 value;
};

class SplatFilm {
public:
    SplatFilm(int width, int height, const Filter& filter);

    void add_splat(const Splat& s);
    // The image for `particles_per_pixel` particles per pixel.
    Image resolve(double particles_per_pixel) const;
    // ∫ f over its support (midpoint rule on a fine grid: exact for the box and the tent).
    double filter_integral() const { return filter_integral_; }
    // The raw sums (rgb per pixel), for adding films of several processes.
    std::span<double> accumulators() { return sums_; }
    std::size_t bytes() const { return sums_.size() * sizeof(double); }

private:
    int width_, height_;
    const Filter& filter_;
    double filter_integral_;
    std::vector<double> sums_; // rgb per pixel
};

} // namespace illum
