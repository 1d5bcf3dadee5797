#include "illum/camera/film.h"

namespace illum {

Image crop(const Image& image, const PixelBounds& b) {
    if (b.x0 == 0 && b.y0 == 0 && b.x1 == image.width() && b.y1 == image.height()) return image;
    Image out(b.width(), b.height());
    for (int y = 0; y < b.height(); ++y)
        for (int x = 0; x < b.width(); ++x) out(x, y) = image(b.x0 + x, b.y0 + y);
    return out;
}

Image Film::resolve() const {
    Image img(width_, height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const double* px = &sums_[(std::size_t(y) * width_ + x) * 4];
            if (px[3] > 0)
                img(x, y) = Color3(float(px[0] / px[3]), float(px[1] / px[3]), float(px[2] / px[3]));
        }
    return img;
}

} // namespace illum
