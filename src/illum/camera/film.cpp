#include "illum/camera/film.h"

namespace illum {

Image Film::resolve() const {
    Image img(width_, height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Pixel& px = pixels_[std::size_t(y) * width_ + x];
            if (px.weight > 0) {
                img(x, y) = Color3(float(px.sum[0] / px.weight), float(px.sum[1] / px.weight),
                                   float(px.sum[2] / px.weight));
            }
        }
    return img;
}

} // namespace illum
