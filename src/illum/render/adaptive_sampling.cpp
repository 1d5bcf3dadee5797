#include "illum/render/adaptive_sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "illum/util/error.h"

namespace illum {

namespace {

constexpr int kWindowRadius = 2;                     // the 5 × 5 window of s̃
constexpr std::uint32_t kMaxPixelSamples = 1u << 24; // a bound on any pixel's samples
constexpr double kFloorFraction = 0.25;              // of the mean, without a threshold
constexpr int kLevelSteps = 40;                      // bisection steps of λ (a ratio of 2^24 to 1e-11)

// The largest power of two not above x (1 below 2).
std::uint32_t power_of_two_floor(double x) {
    if (!(x >= 2)) return 1;
    return std::bit_floor(std::uint32_t(std::min(x, double(kMaxPixelSamples))));
}

// v[i] := the mean of v over the `radius` pixels on either side of i along the rows (or the columns) of a
// w × h raster, clipped at its edges.
void box_average(std::vector<double>& v, int w, int h, bool along_rows, int radius) {
    const int n = along_rows ? w : h, lines = along_rows ? h : w;
    std::vector<double> prefix(std::size_t(n) + 1);
    for (int l = 0; l < lines; ++l) {
        auto at = [&](int i) -> double& {
            return along_rows ? v[std::size_t(l) * w + i] : v[std::size_t(i) * w + l];
        };
        prefix[0] = 0;
        for (int i = 0; i < n; ++i) prefix[std::size_t(i) + 1] = prefix[std::size_t(i)] + at(i);
        for (int i = 0; i < n; ++i) {
            const int a = std::max(0, i - radius), b = std::min(n, i + radius + 1);
            at(i) = (prefix[std::size_t(b)] - prefix[std::size_t(a)]) / double(b - a);
        }
    }
}

} // namespace

AdaptiveSchedule::AdaptiveSchedule(const PixelBounds& bounds, const AdaptiveSettings& settings)
    : bounds_(bounds), settings_(settings) {
    if (bounds.empty()) throw Error("adaptive sampling needs pixels to render");
    if (settings.min_spp < 2 || !std::has_single_bit(unsigned(settings.min_spp)))
        throw Error("adaptive sampling's minimum samples per pixel must be a power of two, at least 2");
    if (!(settings.threshold >= 0) || !std::isfinite(settings.threshold))
        throw Error("adaptive sampling's threshold must be a non-negative number");
    taken_.assign(std::size_t(bounds.width()) * std::size_t(bounds.height()), 0);
    target_ = taken_;
    half_.assign(taken_.size() * 4, 0.0);
}

std::uint64_t AdaptiveSchedule::taken() const {
    std::uint64_t s = 0;
    for (std::uint32_t n : taken_) s += n;
    return s;
}

std::uint32_t AdaptiveSchedule::min_taken() const { return *std::min_element(taken_.begin(), taken_.end()); }
std::uint32_t AdaptiveSchedule::max_taken() const { return *std::max_element(taken_.begin(), taken_.end()); }

std::vector<double> AdaptiveSchedule::smoothed_deviation(const Film& film) const {
    const int w = bounds_.width(), h = bounds_.height();
    std::vector<double> v(taken_.size(), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            const double* s = film.pixel_sums(bounds_.x0 + x, bounds_.y0 + y);
            const double* a = &half_[i * 4];
            const double w_a = a[3], w_b = s[3] - a[3];
            if (!(w_a > 0) || !(w_b > 0)) continue;
            double d = 0;
            for (int c = 0; c < 3; ++c) {
                const double diff = a[c] / w_a - (s[c] - a[c]) / w_b;
                d += diff * diff;
            }
            // n · (A - B)² / 4, averaged over the channels.
            v[i] = double(taken_[i]) * d / 12;
        }
    box_average(v, w, h, true, kWindowRadius);
    box_average(v, w, h, false, kWindowRadius);
    for (double& d : v) d = std::sqrt(std::max(0.0, d));
    return v;
}

std::vector<AdaptiveSchedule::Run> AdaptiveSchedule::round_runs(std::uint64_t max_samples) const {
    std::vector<Run> runs;
    for (int y = bounds_.y0; y < bounds_.y1; ++y) {
        int x0 = -1, x1 = -1;
        std::uint64_t samples = 0;
        for (int x = bounds_.x0; x < bounds_.x1; ++x) {
            const std::uint64_t n = std::uint64_t(to(x, y) - from(x, y));
            if (n == 0) continue;
            if (x0 >= 0 && samples + n > max_samples) {
                runs.push_back({y, x0, x1});
                x0 = -1;
            }
            if (x0 < 0) x0 = x, samples = 0;
            samples += n;
            x1 = x + 1;
        }
        if (x0 >= 0) runs.push_back({y, x0, x1});
    }
    return runs;
}

std::uint64_t AdaptiveSchedule::double_pixels(const Film& film, const std::vector<char>& grow) {
    const int w = bounds_.width();
    std::uint64_t added = 0;
    for (std::size_t i = 0; i < taken_.size(); ++i) {
        target_[i] = taken_[i];
        if (!grow[i]) continue;
        const double* s =
            film.pixel_sums(bounds_.x0 + int(i % std::size_t(w)), bounds_.y0 + int(i / std::size_t(w)));
        std::copy(s, s + 4, &half_[i * 4]);
        target_[i] = 2 * taken_[i];
        added += taken_[i];
    }
    return added;
}

std::uint64_t AdaptiveSchedule::plan(const Film& film, std::uint64_t budget) {
    const std::uint64_t added = plan_round(film, budget);
    if (added > 0) ++rounds_;
    return added;
}

std::uint64_t AdaptiveSchedule::plan_round(const Film& film, std::uint64_t budget) {
    const std::size_t pixels = taken_.size();
    const std::uint64_t taken_now = taken();
    if (rounds_ == 0) {
        const std::uint32_t first = std::min(std::uint32_t(settings_.min_spp / 2),
                                             power_of_two_floor(double(budget) / double(pixels)));
        std::fill(target_.begin(), target_.end(), first);
        return std::uint64_t(first) * pixels;
    }
    if (rounds_ == 1) { // every pixel to min_spp: its two halves
        if (2 * taken_now > budget) return 0;
        return double_pixels(film, std::vector<char>(pixels, 1));
    }
    const std::vector<double> sigma = smoothed_deviation(film);
    double mean = 0;
    for (int y = bounds_.y0; y < bounds_.y1; ++y)
        for (int x = bounds_.x0; x < bounds_.x1; ++x) {
            const double* s = film.pixel_sums(x, y);
            if (s[3] > 0) mean += (s[0] + s[1] + s[2]) / (3 * s[3]);
        }
    mean /= double(pixels);

    const bool thresholded = settings_.threshold > 0;
    const double floor_samples =
        thresholded ? double(settings_.min_spp)
                    : std::max(double(settings_.min_spp),
                               double(power_of_two_floor(kFloorFraction * double(budget) / double(pixels))));
    // λ: the level at which max(n_p, floor, s̃_p / λ) sums to the budget (the sum falls as λ grows), by
    // bisection of its logarithm.
    double base_total = 0, sigma_max = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        base_total += std::max(double(taken_[i]), floor_samples);
        sigma_max = std::max(sigma_max, sigma[i]);
    }
    auto total_at = [&](double lambda) {
        double t = 0;
        for (std::size_t i = 0; i < pixels; ++i)
            t += std::max({double(taken_[i]), floor_samples, sigma[i] / lambda});
        return t;
    };
    double lambda = std::numeric_limits<double>::infinity();
    if (sigma_max > 0 && base_total < double(budget)) {
        double hi = sigma_max, lo = sigma_max / double(kMaxPixelSamples);
        for (int step = 0; step < kLevelSteps; ++step) {
            const double mid = std::sqrt(lo * hi);
            (total_at(mid) <= double(budget) ? hi : lo) = mid;
        }
        lambda = hi;
    }
    if (thresholded) lambda = std::max(lambda, settings_.threshold * mean);
    if (mean > 0 && std::isfinite(lambda)) level_ = lambda / mean;

    // The pixels to double: those whose target is above √2 times their samples, by how far below it they
    // are while the budget lasts.
    std::vector<std::pair<double, std::uint32_t>> wanted; // (target / samples, pixel)
    for (std::size_t i = 0; i < pixels; ++i) {
        const double target = std::max(floor_samples, std::isfinite(lambda) ? sigma[i] / lambda : 0.0);
        const double n = taken_[i];
        if (target > std::sqrt(2.0) * n && 2 * n <= double(kMaxPixelSamples))
            wanted.push_back({target / n, std::uint32_t(i)});
    }
    std::sort(wanted.begin(), wanted.end(), [](const auto& a, const auto& b) {
        return a.first > b.first || (a.first == b.first && a.second < b.second);
    });
    std::uint64_t left = budget > taken_now ? budget - taken_now : 0;
    std::vector<char> grow(pixels, 0);
    for (const auto& [ratio, i] : wanted) {
        if (taken_[i] > left) continue;
        left -= taken_[i];
        grow[i] = 1;
    }
    return double_pixels(film, grow);
}

} // namespace illum
