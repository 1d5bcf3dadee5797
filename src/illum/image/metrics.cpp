#include "illum/image/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "illum/util/error.h"

namespace illum {

namespace {

void require_same_size(const Image& a, const Image& b, const char* what) {
    if (a.width() != b.width() || a.height() != b.height())
        throw Error(std::string(what) + ": image sizes differ (" + std::to_string(a.width()) + "x" +
                    std::to_string(a.height()) + " vs " + std::to_string(b.width()) + "x" +
                    std::to_string(b.height()) + ")");
}

// Mean over the pixels of term(a_c, b_c) for each channel c: all pixels, or only those where both images
// are finite when `finite_only` (0 when no pixel is left).
template <class Term>
ErrorStats mean_of(const Image& a, const Image& b, const char* what, Term term, bool finite_only = false) {
    require_same_size(a, b, what);
    ErrorStats s;
    std::array<double, 3> sum{0, 0, 0};
    std::size_t n = 0;
    const Color3* pa = a.data();
    const Color3* pb = b.data();
    for (std::size_t i = 0; i < a.pixel_count(); ++i) {
        if (finite_only && !(is_finite_pixel(pa[i]) && is_finite_pixel(pb[i]))) continue;
        ++n;
        for (int c = 0; c < 3; ++c) sum[c] += term(double(pa[i][c]), double(pb[i][c]));
    }
    if (n == 0) return s;
    for (int c = 0; c < 3; ++c) s.channel[c] = sum[c] / double(n);
    s.overall = (sum[0] + sum[1] + sum[2]) / (3.0 * double(n));
    return s;
}

ErrorStats means_of(const Image& image, bool finite_only) {
    ErrorStats s;
    std::array<double, 3> sum{0, 0, 0};
    std::size_t n = 0;
    const Color3* p = image.data();
    for (std::size_t i = 0; i < image.pixel_count(); ++i) {
        if (finite_only && !is_finite_pixel(p[i])) continue;
        ++n;
        for (int c = 0; c < 3; ++c) sum[c] += p[i][c];
    }
    if (n == 0) return s;
    for (int c = 0; c < 3; ++c) s.channel[c] = sum[c] / double(n);
    s.overall = (s.channel[0] + s.channel[1] + s.channel[2]) / 3.0;
    return s;
}

ErrorStats relative_difference(const ErrorStats& ma, const ErrorStats& mb) {
    auto rel = [](double x, double y) {
        if (y != 0) return (x - y) / y;
        if (x == 0) return 0.0;
        return std::copysign(std::numeric_limits<double>::infinity(), x);
    };
    ErrorStats s;
    for (int c = 0; c < 3; ++c) s.channel[c] = rel(ma.channel[c], mb.channel[c]);
    s.overall = rel(ma.overall, mb.overall);
    return s;
}

double squared_error(double x, double y) { return (x - y) * (x - y); }

} // namespace

ErrorStats mse(const Image& a, const Image& reference) { return mean_of(a, reference, "mse", squared_error); }

ErrorStats rmse(const Image& a, const Image& reference) {
    ErrorStats s = mse(a, reference);
    for (double& c : s.channel) c = std::sqrt(c);
    s.overall = std::sqrt(s.overall);
    return s;
}

ErrorStats rel_mse(const Image& a, const Image& reference, double eps) {
    return mean_of(a, reference, "relmse",
                   [eps](double x, double y) { return (x - y) * (x - y) / (y * y + eps); });
}

ErrorStats mean_relative_error(const Image& a, const Image& reference, double eps) {
    return mean_of(a, reference, "mean relative error",
                   [eps](double x, double y) { return std::abs(x - y) / (std::abs(y) + eps); });
}

ErrorStats channel_means(const Image& image) { return means_of(image, false); }

ErrorStats relative_mean_difference(const Image& a, const Image& reference) {
    return relative_difference(channel_means(a), channel_means(reference));
}

std::size_t count_nonfinite_pixels(const Image& image) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i) n += !is_finite_pixel(image.data()[i]);
    return n;
}

ErrorStats trimmed_rmse(const Image& a, const Image& reference, double fraction, std::size_t* trimmed) {
    require_same_size(a, reference, "trimmed rmse");
    if (!(fraction >= 0 && fraction < 1))
        throw Error("trimmed rmse: the fraction left out must be in [0, 1), got " + std::to_string(fraction));
    // Each finite pixel's squared error over the channels, with its index.
    std::vector<std::pair<double, std::size_t>> errors;
    errors.reserve(a.pixel_count());
    const Color3* pa = a.data();
    const Color3* pb = reference.data();
    for (std::size_t i = 0; i < a.pixel_count(); ++i) {
        if (!(is_finite_pixel(pa[i]) && is_finite_pixel(pb[i]))) continue;
        double e = 0;
        for (int c = 0; c < 3; ++c) e += squared_error(pa[i][c], pb[i][c]);
        errors.push_back({e, i});
    }
    const std::size_t drop =
        std::min(errors.size(), std::size_t(std::floor(fraction * double(errors.size()))));
    if (trimmed) *trimmed = drop;
    ErrorStats s;
    const std::size_t keep = errors.size() - drop;
    if (keep == 0) return s;
    // The `keep` smallest errors first (ties broken by index, so the result does not depend on the sort).
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(keep), errors.end());
    std::array<double, 3> sum{0, 0, 0};
    for (std::size_t k = 0; k < keep; ++k) {
        const std::size_t i = errors[k].second;
        for (int c = 0; c < 3; ++c) sum[c] += squared_error(pa[i][c], pb[i][c]);
    }
    for (int c = 0; c < 3; ++c) s.channel[c] = std::sqrt(sum[c] / double(keep));
    s.overall = std::sqrt((sum[0] + sum[1] + sum[2]) / (3.0 * double(keep)));
    return s;
}

FiniteComparison compare_finite(const Image& a, const Image& reference, double eps, double trim) {
    FiniteComparison r;
    r.nonfinite = count_nonfinite_pixels(a);
    r.reference_nonfinite = count_nonfinite_pixels(reference);
    r.mean = means_of(a, true);
    r.reference_mean = means_of(reference, true);
    r.relative_mean_difference = relative_difference(r.mean, r.reference_mean);
    if (a.width() != reference.width() || a.height() != reference.height()) return r;
    for (std::size_t i = 0; i < a.pixel_count(); ++i)
        r.compared += is_finite_pixel(a.data()[i]) && is_finite_pixel(reference.data()[i]);
    ErrorStats m = mean_of(a, reference, "mse", squared_error, true);
    for (double& c : m.channel) c = std::sqrt(c);
    m.overall = std::sqrt(m.overall);
    r.rmse = m;
    r.rel_mse = mean_of(
        a, reference, "relmse", [eps](double x, double y) { return squared_error(x, y) / (y * y + eps); },
        true);
    r.mean_relative_error = mean_of(
        a, reference, "mean relative error",
        [eps](double x, double y) { return std::abs(x - y) / (std::abs(y) + eps); }, true);
    r.rmse_trimmed = trimmed_rmse(a, reference, trim, &r.trimmed);
    return r;
}

Image downsample(const Image& image, int factor) {
    if (factor < 1) throw Error("downsample: factor must be at least 1, got " + std::to_string(factor));
    if (image.width() % factor != 0 || image.height() % factor != 0)
        throw Error("downsample: " + std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                    " is not a multiple of " + std::to_string(factor));
    Image out(image.width() / factor, image.height() / factor);
    const double inv_area = 1.0 / (double(factor) * double(factor));
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            double sum[3] = {0, 0, 0};
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i) {
                    const Color3& p = image(x * factor + i, y * factor + j);
                    sum[0] += p.r;
                    sum[1] += p.g;
                    sum[2] += p.b;
                }
            out(x, y) = {float(sum[0] * inv_area), float(sum[1] * inv_area), float(sum[2] * inv_area)};
        }
    return out;
}

} // namespace illum
