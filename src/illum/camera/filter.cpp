#include "illum/camera/filter.h"

#include <algorithm>
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
    g_peak_ = gaussian(0, sigma_);
    for (int axis = 0; axis < 2; ++axis) {
        const std::size_t a = std::size_t(axis);
        const double r = radius_[axis];
        g_edge_[a] = gaussian(r, sigma_);
        erf_low_[a] = std::erf(-r / (double(sigma_) * std::sqrt(2.0)));
        total_[a] = gaussian_cdf_unnormalised(r, r, sigma_);
        for (int k = 0; k <= kTableSize; ++k)
            inverse_cdf_[a][std::size_t(k)] = float(invert_cdf(double(k) / kTableSize, axis));
        inverse_cdf_[a][0] = float(-r);
        inverse_cdf_[a][kTableSize] = float(r);
    }
}

float GaussianFilter::evaluate(Vector2f p) const {
    if (std::abs(p.x) > radius_.x || std::abs(p.y) > radius_.y) return 0;
    double gx = std::max(0.0, gaussian(p.x, sigma_) - gaussian(radius_.x, sigma_));
    double gy = std::max(0.0, gaussian(p.y, sigma_) - gaussian(radius_.y, sigma_));
    return float(gx * gy);
}

double GaussianFilter::invert_cdf(double u, int axis) const {
    const double r = radius_[axis];
    const double target = u * total_[std::size_t(axis)];
    // Newton's method from x = 0 with bisection fallback; the CDF is monotone on [-r, r].
    double lo = -r, hi = r, x = 0;
    for (int i = 0; i < 60; ++i) {
        double f = gaussian_cdf_unnormalised(x, r, sigma_) - target;
        if (std::abs(f) < 1e-12 * total_[std::size_t(axis)]) break;
        if (f > 0)
            hi = x;
        else
            lo = x;
        double df = gaussian(x, sigma_) - g_edge_[std::size_t(axis)];
        double xn = df > 0 ? x - f / df : 0.5 * (lo + hi);
        x = (xn > lo && xn < hi) ? xn : 0.5 * (lo + hi);
    }
    return x;
}

float GaussianFilter::sample_axis(float u, int axis) const {
    const std::size_t a = std::size_t(axis);
    const double r = radius_[axis];
    double s = double(u) * kTableSize;
    int i = std::min(int(s), kTableSize - 1);
    double x = std::lerp(double(inverse_cdf_[a][std::size_t(i)]), double(inverse_cdf_[a][std::size_t(i) + 1]),
                         s - i);
    // Newton's steps on CDF(x) = u · total. Each squares the error, times |g'| / 2(g - g(r)), at most about
    // 6 r/σ² where the steps are taken, so once a step is below 1e-4 σ²/r the error left is below 1e-7 of
    // x's scale, float's resolution: usually after one step from the table. Near the ends, where the
    // inverse is steep
    // and the density vanishes, the table's guess is poor: there (rarely, the ends hold little of the
    // filter) the slow inversion.
    // (gaussian_cdf_unnormalised written out with the axis' constants: one erf and one exp a step.)
    const double target = double(u) * total_[a];
    const double inv_s = 1 / (double(sigma_) * std::sqrt(2.0));
    for (int step = 0; step < 4; ++step) {
        double df = g_peak_ * std::exp(-(x * inv_s) * (x * inv_s)) - g_edge_[a];
        if (!(df > 1e-3 * (g_peak_ - g_edge_[a]))) break;
        double cdf = 0.5 * (std::erf(x * inv_s) - erf_low_[a]) - g_edge_[a] * (x + r);
        double dx = (cdf - target) / df;
        x -= dx;
        if (std::abs(dx) < 1e-4 * double(sigma_) * double(sigma_) / r) return float(std::clamp(x, -r, r));
    }
    return float(invert_cdf(double(u), axis));
}

FilterSample GaussianFilter::sample(Point2f u) const {
    return {{sample_axis(u.x, 0), sample_axis(u.y, 1)}, 1};
}

void TabulatedFilter::tabulate() {
    nx_ = std::max(1, int(32 * radius_.x));
    ny_ = std::max(1, int(32 * radius_.y));
    f_.resize(std::size_t(nx_) * std::size_t(ny_));
    std::vector<float> magnitude(f_.size());
    for (int y = 0; y < ny_; ++y)
        for (int x = 0; x < nx_; ++x) {
            Vector2f p{(2 * (x + 0.5f) / nx_ - 1) * radius_.x, (2 * (y + 0.5f) / ny_ - 1) * radius_.y};
            float v = evaluate(p);
            f_[std::size_t(y) * nx_ + x] = v;
            magnitude[std::size_t(y) * nx_ + x] = std::abs(v);
        }
    distribution_ = Distribution2D(magnitude, nx_, ny_);
}

FilterSample TabulatedFilter::sample(Point2f u) const {
    float pdf = 0;
    Point2f q = distribution_.sample(u, &pdf); // density per unit area of [0, 1)²
    int x = std::min(int(q.x * nx_), nx_ - 1), y = std::min(int(q.y * ny_), ny_ - 1);
    // Per unit area of the filter's domain, 2r_x × 2r_y pixels.
    float pdf_area = pdf / (4 * radius_.x * radius_.y);
    float f = f_[std::size_t(y) * nx_ + x];
    return {{(2 * q.x - 1) * radius_.x, (2 * q.y - 1) * radius_.y}, pdf_area > 0 ? f / pdf_area : 0.0f};
}

MitchellFilter::MitchellFilter(Vector2f radius, float b, float c) : TabulatedFilter(radius), b_(b), c_(c) {
    tabulate();
}

float MitchellFilter::mitchell_1d(float x, float b, float c) {
    x = std::abs(x);
    if (x <= 1) return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
    if (x <= 2)
        return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x +
                (8 * b + 24 * c)) /
               6;
    return 0;
}

float MitchellFilter::evaluate(Vector2f p) const {
    return mitchell_1d(2 * p.x / radius_.x, b_, c_) * mitchell_1d(2 * p.y / radius_.y, b_, c_);
}

LanczosSincFilter::LanczosSincFilter(Vector2f radius, float tau) : TabulatedFilter(radius), tau_(tau) {
    tabulate();
}

namespace {

float sinc(float x) {
    if (std::abs(x) < 1e-5f) return 1 - kPi * kPi * x * x / 6; // sin(πx)/(πx) ≈ 1 - (πx)²/6
    return std::sin(kPi * x) / (kPi * x);
}

float windowed_sinc(float x, float radius, float tau) {
    return std::abs(x) > radius ? 0 : sinc(x) * sinc(x / tau);
}

} // namespace

float LanczosSincFilter::evaluate(Vector2f p) const {
    return windowed_sinc(p.x, radius_.x, tau_) * windowed_sinc(p.y, radius_.y, tau_);
}

std::unique_ptr<Filter> make_filter(const std::string& name, Vector2f radius, float sigma) {
    auto pick = [&](Vector2f def) {
        return Vector2f{radius.x > 0 ? radius.x : def.x, radius.y > 0 ? radius.y : def.y};
    };
    if (name == "box") return std::make_unique<BoxFilter>(pick({0.5f, 0.5f}));
    if (name == "triangle") return std::make_unique<TriangleFilter>(pick({2, 2}));
    if (name == "gaussian") return std::make_unique<GaussianFilter>(pick({1.5f, 1.5f}), sigma);
    if (name == "mitchell") return std::make_unique<MitchellFilter>(pick({2, 2}));
    if (name == "sinc") return std::make_unique<LanczosSincFilter>(pick({4, 4}));
    throw Error("unknown pixel filter \"" + name + "\" (use box, triangle, gaussian, mitchell or sinc)");
}

} // namespace illum
