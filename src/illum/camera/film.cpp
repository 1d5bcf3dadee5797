#include "illum/camera/film.h"

namespace illum {

Image Film::resolve() const {
    Image img(width_, height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const double* px = &sums_[(std::size_t(y) * width_ + x) * 4];
            if (px[3] > 0) img(x, y) = Color3(float(px[0] / px[3]), float(px[1] / px[3]), float(px[2] / px[3]));
        }
    return img;
}

} // namespace illum
