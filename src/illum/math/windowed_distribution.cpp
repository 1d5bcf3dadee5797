#include "illum/math/windowed_distribution.h"

#include <algorithm>
#include <cmath>

namespace illum {

WindowedDistribution2D::WindowedDistribution2D(std::span<const float> weights, int nu, int nv)
    : nu_(nu), nv_(nv), f_(weights.size()), sat_(std::size_t(nu + 1) * std::size_t(nv + 1), 0.0) {
    for (std::size_t k = 0; k < weights.size(); ++k)
        f_[k] = (weights[k] > 0 && std::isfinite(weights[k])) ? weights[k] : 0.0f;
    for (int j = 0; j < nv; ++j) {
        double row = 0;
        for (int i = 0; i < nu; ++i) {
            row += f(i, j);
            sat_[std::size_t(j + 1) * std::size_t(nu + 1) + std::size_t(i + 1)] = s(i + 1, j) + row;
        }
    }
}

double WindowedDistribution2D::g(double x, double y) const {
    x = std::clamp(x, 0.0, double(nu_));
    y = std::clamp(y, 0.0, double(nv_));
    int i = std::min(int(x), nu_ - 1), j = std::min(int(y), nv_ - 1);
    double fx = x - i, fy = y - j;
    return (1 - fx) * (1 - fy) * s(i, j) + fx * (1 - fy) * s(i + 1, j) + (1 - fx) * fy * s(i, j + 1) +
           fx * fy * s(i + 1, j + 1);
}

double WindowedDistribution2D::row_prefix(int j, double x) const { return g(x, j + 1) - g(x, j); }

double WindowedDistribution2D::integral(Point2f lo, Point2f hi) const {
    if (nu_ <= 0 || nv_ <= 0 || !(hi.x > lo.x) || !(hi.y > lo.y)) return 0;
    double x0 = double(lo.x) * nu_, x1 = double(hi.x) * nu_, y0 = double(lo.y) * nv_, y1 = double(hi.y) * nv_;
    return (g(x1, y1) - g(x0, y1) - g(x1, y0) + g(x0, y0)) / (double(nu_) * nv_);
}

float WindowedDistribution2D::pdf(Point2f p, Point2f lo, Point2f hi) const {
    if (!(p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)) return 0;
    double total = integral(lo, hi);
    if (!(total > 0)) return 0;
    int i = std::clamp(int(double(p.x) * nu_), 0, nu_ - 1),
        j = std::clamp(int(double(p.y) * nv_), 0, nv_ - 1);
    return float(f(i, j) / total);
}

std::optional<Point2f> WindowedDistribution2D::sample(Point2f u, Point2f lo, Point2f hi, float* pdf) const {
    if (nu_ <= 0 || nv_ <= 0 || !(hi.x > lo.x) || !(hi.y > lo.y)) return std::nullopt;
    const double x0 = double(lo.x) * nu_, x1 = double(hi.x) * nu_, y0 = double(lo.y) * nv_,
                 y1 = double(hi.y) * nv_;
    // The window's mass below y (cell units), increasing in y.
    auto below = [&](double y) { return g(x1, y) - g(x0, y) - g(x1, y0) + g(x0, y0); };
    const double total = below(y1);
    if (!(total > 0)) return std::nullopt;
    // Row: the last row boundary whose mass is <= the target, between floor(y0) and ceil(y1).
    const double target_y = std::clamp(double(u.y), 0.0, 1.0) * total;
    int jlo = std::clamp(int(std::floor(y0)), 0, nv_ - 1),
        jhi = std::clamp(int(std::ceil(y1)) - 1, jlo, nv_ - 1);
    while (jlo < jhi) { // find the row j whose span [max(j, y0), min(j + 1, y1)] holds the target
        int mid = (jlo + jhi + 1) / 2;
        if (below(std::max(double(mid), y0)) <= target_y)
            jlo = mid;
        else
            jhi = mid - 1;
    }
    int j = jlo;
    // Skip rows of zero mass in the window (the target then sits at their boundary).
    double row_mass = row_prefix(j, x1) - row_prefix(j, x0); // per unit of y within row j
    while (!(row_mass > 0) && j + 1 < nv_ && double(j + 1) < y1) {
        ++j;
        row_mass = row_prefix(j, x1) - row_prefix(j, x0);
    }
    if (!(row_mass > 0)) return std::nullopt;
    double ystart = std::max(double(j), y0);
    double y =
        std::clamp(ystart + (target_y - below(ystart)) / row_mass, ystart, std::min(double(j + 1), y1));
    // Column within row j: the conditional's CDF is row_prefix(j, x) - row_prefix(j, x0).
    const double target_x = std::clamp(double(u.x), 0.0, 1.0) * row_mass + row_prefix(j, x0);
    int ilo = std::clamp(int(std::floor(x0)), 0, nu_ - 1),
        ihi = std::clamp(int(std::ceil(x1)) - 1, ilo, nu_ - 1);
    while (ilo < ihi) {
        int mid = (ilo + ihi + 1) / 2;
        if (row_prefix(j, std::max(double(mid), x0)) <= target_x)
            ilo = mid;
        else
            ihi = mid - 1;
    }
    int i = ilo;
    while (!(f(i, j) > 0) && i + 1 < nu_ && double(i + 1) < x1) ++i;
    if (!(f(i, j) > 0)) return std::nullopt;
    double xstart = std::max(double(i), x0);
    double x = std::clamp(xstart + (target_x - row_prefix(j, xstart)) / f(i, j), xstart,
                          std::min(double(i + 1), x1));
    // Keep the point inside its cell after rounding to float, so pdf() names the same cell.
    Point2f p{float(x / nu_), float(y / nv_)};
    p.x = std::clamp(p.x, lo.x, hi.x);
    p.y = std::clamp(p.y, lo.y, hi.y);
    for (int k = 0; k < 2; ++k) {
        int ci = std::clamp(int(double(p.x) * nu_), 0, nu_ - 1),
            cj = std::clamp(int(double(p.y) * nv_), 0, nv_ - 1);
        if (ci > i) p.x = std::nextafter(p.x, 0.0f);
        if (ci < i) p.x = std::nextafter(p.x, 1.0f);
        if (cj > j) p.y = std::nextafter(p.y, 0.0f);
        if (cj < j) p.y = std::nextafter(p.y, 1.0f);
    }
    if (std::clamp(int(double(p.x) * nu_), 0, nu_ - 1) != i ||
        std::clamp(int(double(p.y) * nv_), 0, nv_ - 1) != j)
        return std::nullopt;
    if (pdf) *pdf = float(f(i, j) / (total / (double(nu_) * nv_)));
    return p;
}

} // namespace illum
