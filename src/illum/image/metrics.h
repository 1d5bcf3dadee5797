// Error metrics between an image and a reference, summed in double. Every metric that compares pixel by
// pixel requires equal sizes and throws illum::Error otherwise. Non-finite pixels are not skipped: they
// make the result NaN or infinite, which is what a comparison should report. compare_finite() is the
// other choice, for a report (`illum diff`): it leaves them out and says how many it left out.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include "illum/image/image.h"

namespace illum {

// A metric per channel (r, g, b) and over all three channels together.
struct ErrorStats {
    std::array<double, 3> channel{0, 0, 0};
    double overall = 0;
};

// The eps of the relative metrics, as in the denoising and rendering literature (e.g. Rousselle et al.
// 2011, Bako et al. 2017): it keeps near-black reference pixels from dominating the average.
constexpr double kRelativeEps = 1e-2;

// Mean squared error, mean over pixels of (a - b)^2. `overall` is the mean over all 3 * N values.
ErrorStats mse(const Image& a, const Image& reference);
// sqrt of the MSE (per channel, and sqrt of the overall MSE).
ErrorStats rmse(const Image& a, const Image& reference);
// Relative MSE, mean of (a - b)^2 / (b^2 + eps), with b the reference.
ErrorStats rel_mse(const Image& a, const Image& reference, double eps = kRelativeEps);
// Mean relative (absolute) error, mean of |a - b| / (|b| + eps).
ErrorStats mean_relative_error(const Image& a, const Image& reference, double eps = kRelativeEps);

// The RMSE without the pixels of the largest errors: the floor(fraction · N) pixels whose squared error
// summed over the channels is largest are left out (pixels with an Inf or NaN in either image are left out
// first and not counted in N). Fireflies, rare paths to emitters smaller than a pixel that neither a short
// render nor the reference resolves, decide the plain RMSE by luck; this one says how the rest compares.
// *trimmed (optional): how many pixels were left out for their error.
ErrorStats trimmed_rmse(const Image& a, const Image& reference, double fraction,
                        std::size_t* trimmed = nullptr);
// `illum diff`'s default fraction: 16 pixels of a 128 × 128 image, none of an image under 1000 pixels.
constexpr double kTrimFraction = 1e-3;

// Per-channel means in double; `overall` is the mean of the three. Zero for an empty image.
ErrorStats channel_means(const Image& image);
// (mean(a) - mean(b)) / mean(b) per channel and for the overall means; the images may differ in size.
// When a reference mean is 0 the entry is 0 if the other mean is 0 too and +-inf otherwise.
ErrorStats relative_mean_difference(const Image& a, const Image& reference);

// True when every channel of the pixel is finite (no Inf, no NaN).
inline bool is_finite_pixel(const Color3& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
// The number of pixels with an Inf or NaN in some channel.
std::size_t count_nonfinite_pixels(const Image& image);

// The figures of `illum diff` without the pixels that have an Inf or NaN: one such pixel would make every
// figure Inf or NaN and hide what the rest of the image says. Each mean is over that image's finite
// pixels; the per-pixel metrics (present when the sizes agree) are over the pixels finite in both.
struct FiniteComparison {
    std::size_t nonfinite = 0, reference_nonfinite = 0; // pixels left out of each image's mean
    std::size_t compared = 0; // pixels in the per-pixel metrics (finite in both); 0 when sizes differ
    ErrorStats mean, reference_mean, relative_mean_difference;
    std::optional<ErrorStats> rmse, rel_mse, mean_relative_error; // when the sizes agree
    std::optional<ErrorStats> rmse_trimmed;                       // trimmed_rmse(trim), when the sizes agree
    std::size_t trimmed = 0;                                      // the pixels it left out for their error
};
FiniteComparison compare_finite(const Image& a, const Image& reference, double eps = kRelativeEps,
                                double trim = kTrimFraction);

// Box-filters the image down by an integer factor: each output pixel is the mean of a factor x factor
// block. The width and height must be multiples of factor (throws illum::Error otherwise).
Image downsample(const Image& image, int factor);

} // namespace illum
