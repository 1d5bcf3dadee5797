#include "illum/camera/filter.h"

#include <cmath>
#include <stdexcept>

#include "illum/util/error.h"

namespace illum {

namespace {
double gaussian(double x, double sigma) {
    return std::exp(-x * x / (2 * sigma * sigma)) / std::sqrt(2 * 3.14159265358979323846 * sigma * sigma);
}
// ∫_{-r}^{x} (g(t) - g(r)) dt.
double gaussian_cdf_unnormalised(double x, double r, double sigma) {
    double s = sigma * std::sqrt(2.0);
    return 0.5 * (std::erf(x / s) - std::erf(-r / s)) - gaussian(r, sigma) * (x + r);
}
} // namespace

GaussianFilter::GaussianFilter(Vector2f radius, float sigma) : Filter(radius), sigma_(sigma) {
    if (!(sigma > 0)) throw Error("gaussian filter: sigma must be positive");
}

float GaussianFilter::evaluate(Vector2f p) const {
    if (std::abs(p.x) > radius_.x || std::abs(p.y) > radius_.y) return 0;
    double gx = std::max(0.0, gaussian(p.x, sigma_) - gaussian(radius_.x, sigma_));
    double gy = std::max(0.0, gaussian(p.y, sigma_) - gaussian(radius_.y, sigma_));
    return float(gx * gy);
}

float GaussianFilter::sample_axis(float u, float r) const {
    double total = gaussian_cdf_unnormalised(r, r, sigma_);
    double target = u * total;
    // Newton's method from x = 0 with bisection fallback; the CDF is monotone on [-r, r].
    double lo = -r, hi = r, x = 0;
    for (int i = 0; i < 40; ++i) {
        double f = gaussian_cdf_unnormalised(x, r, sigma_) - target;
        if (std::abs(f) < 1e-9 * total) break;
        if (f > 0)
            hi = x;
        else
            lo = x;
        double df = gaussian(x, sigma_) - gaussian(r, sigma_);
        double xn = df > 0 ? x - f / df : 0.5 * (lo + hi);
        x = (xn > lo && xn < hi) ? xn : 0.5 * (lo + hi);
    }
    return float(x);
}

FilterSample GaussianFilter::sample(Point2f u) const {
    return {{sample_axis(u.x, radius_.x), sample_axis(u.y, radius_.y)}, 1};
}

std::unique_ptr<Filter> make_filter(const std::string& name, Vector2f radius, float sigma) {
    auto pick = [&](Vector2f def) {
        return Vector2f{radius.x > 0 ? radius.x : def.x, radius.y > 0 ? radius.y : def.y};
    };
    if (name == "box") return std::make_unique<BoxFilter>(pick({0.5f, 0.5f}));
    if (name == "triangle") return std::make_unique<TriangleFilter>(pick({2, 2}));
    if (name == "gaussian") return std::make_unique<GaussianFilter>(pick({1.5f, 1.5f}), sigma);
    throw Error("unknown pixel filter \"" + name + "\" (use box, triangle or gaussian)");
}

} // namespace illum
