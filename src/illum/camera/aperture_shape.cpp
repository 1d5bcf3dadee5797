#include "illum/camera/aperture_shape.h"

#include <array>
#include <cmath>
#include <vector>

#include "illum/math/vector.h"
#include "illum/util/error.h"

namespace illum {

namespace {

// exp(-r²) - exp(-1) inside the unit disk; ∫ = π (1 - 2/e).
class GaussianAperture final : public ApertureShape {
public:
    double transmission(double u, double v) const override {
        double r2 = u * u + v * v;
        return r2 < 1 ? (std::exp(-r2) - std::exp(-1.0)) / (1 - 2 / std::exp(1.0)) : 0;
    }
};

// A simple polygon (crossing-number inside test), uniform inside, its area found by the shoelace formula.
class PolygonAperture final : public ApertureShape {
public:
    explicit PolygonAperture(std::vector<std::array<double, 2>> v) : v_(std::move(v)) {
        double area2 = 0;
        for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++)
            area2 += v_[j][0] * v_[i][1] - v_[i][0] * v_[j][1];
        value_ = kPiD / (0.5 * std::abs(area2));
    }
    double transmission(double u, double v) const override {
        bool inside = false;
        for (std::size_t i = 0, j = v_.size() - 1; i < v_.size(); j = i++) {
            const auto &a = v_[i], &b = v_[j];
            if ((a[1] > v) != (b[1] > v) && u < a[0] + (v - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
                inside = !inside;
        }
        return inside ? value_ : 0;
    }

private:
    std::vector<std::array<double, 2>> v_;
    double value_;
};

std::vector<std::array<double, 2>> star_or_polygon(int corners, double outer, double inner,
                                                   double start_deg) {
    std::vector<std::array<double, 2>> v;
    int n = inner > 0 ? 2 * corners : corners;
    for (int i = 0; i < n; ++i) {
        double r = inner > 0 && i % 2 == 0 ? inner : outer; // a star starts at an inner corner
        double a = (start_deg + 360.0 * i / n) * kPiD / 180;
        v.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return v;
}

class ImageAperture final : public ApertureShape {
public:
    explicit ImageAperture(const Image& im) : w_(im.width()), h_(im.height()), y_(std::size_t(w_) * h_) {
        double sum = 0;
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x) {
                const Color3& c = im(x, y);
                y_[std::size_t(y) * w_ + x] = (double(c[0]) + c[1] + c[2]) / 3;
                sum += y_[std::size_t(y) * w_ + x];
            }
        if (!(sum > 0)) throw Error("aperture image is black");
        double scale = (kPiD / 4) / (sum / (double(w_) * h_));
        for (double& p : y_) p *= scale;
    }
    // Bilinear in pixel centres, black outside; row 0 (the file's top) at v = +1.
    double transmission(double u, double v) const override {
        double px = (u + 1) / 2 * w_ - 0.5, py = (1 - v) / 2 * h_ - 0.5;
        int x0 = int(std::floor(px)), y0 = int(std::floor(py));
        double fx = px - x0, fy = py - y0;
        return (1 - fx) * (1 - fy) * at(x0, y0) + fx * (1 - fy) * at(x0 + 1, y0) +
               (1 - fx) * fy * at(x0, y0 + 1) + fx * fy * at(x0 + 1, y0 + 1);
    }

private:
    double at(int x, int y) const {
        return x < 0 || y < 0 || x >= w_ || y >= h_ ? 0 : y_[std::size_t(y) * w_ + x];
    }
    int w_, h_;
    std::vector<double> y_;
};

} // namespace

bool is_builtin_aperture(const std::string& name) {
    return name == "gaussian" || name == "square" || name == "pentagon" || name == "star";
}

std::shared_ptr<const ApertureShape> builtin_aperture(const std::string& name) {
    if (name == "gaussian") return std::make_shared<GaussianAperture>();
    // |u|, |v| < 1/2.
    if (name == "square")
        return std::make_shared<PolygonAperture>(
            std::vector<std::array<double, 2>>{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    // A regular pentagon of circumradius 0.8, apex at -v (pbrt-v4's, flipped as its image is).
    if (name == "pentagon") return std::make_shared<PolygonAperture>(star_or_polygon(5, 0.8, 0, -90));
    // A five-pointed star: tips on the unit circle at 36° + 72° k (one at 180°), inner corners at radius
    // cos 72° / cos 36° (the pentagram's), as pbrt-v4's.
    if (name == "star")
        return std::make_shared<PolygonAperture>(
            star_or_polygon(5, 1.0, std::cos(72 * kPiD / 180) / std::cos(36 * kPiD / 180), 0));
    return nullptr;
}

std::shared_ptr<const ApertureShape> image_aperture(const Image& image) {
    if (image.empty()) throw Error("aperture image is empty");
    return std::make_shared<ImageAperture>(image);
}

} // namespace illum
