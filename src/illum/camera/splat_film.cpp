#include "illum/camera/splat_film.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {
double integrate(const Filter& f) {
    // An even number of cells per axis puts the tent's kink on a cell edge: the midpoint rule is exact on
    // each linear piece.
    constexpr int n = 256;
    Vector2f r = f.radius();
    double dx = 2.0 * r.x / n, dy = 2.0 * r.y / n, sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            sum += f.evaluate({float(-r.x + (i + 0.5) * dx), float(-r.y + (j + 0.5) * dy)});
    return sum * dx * dy;
}
} // namespace

SplatFilm::SplatFilm(int width, int height, const Filter& filter)
    : width_(width), height_(height), filter_(filter), filter_integral_(integrate(filter)),
      sums_(std::size_t(width) * height * 3, 0.0) {}

void SplatFilm::add_splat(const Splat& s) {
    // Pixels whose centres (x + 0.5, y + 0.5) lie within the filter radius of the splat.
    Vector2f r = filter_.radius();
    int x0 = std::max(0, int(std::ceil(s.p_raster.x - 0.5f - r.x)));
    int x1 = std::min(width_ - 1, int(std::floor(s.p_raster.x - 0.5f + r.x)));
    int y0 = std::max(0, int(std::ceil(s.p_raster.y - 0.5f - r.y)));
    int y1 = std::min(height_ - 1, int(std::floor(s.p_raster.y - 0.5f + r.y)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            float w = filter_.evaluate({x + 0.5f - s.p_raster.x, y + 0.5f - s.p_raster.y});
            if (w == 0) continue;
            double* px = &sums_[(std::size_t(y) * width_ + x) * 3];
            for (int c = 0; c < 3; ++c) px[c] += double(w) * s.value[c];
        }
}

Image SplatFilm::resolve(double particles_per_pixel) const {
    Image img(width_, height_);
    double scale = particles_per_pixel > 0 ? 1 / (particles_per_pixel * filter_integral_) : 0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const double* px = &sums_[(std::size_t(y) * width_ + x) * 3];
            img(x, y) = Color3(float(px[0] * scale), float(px[1] * scale), float(px[2] * scale));
        }
    return img;
}

} // namespace illum
