// Error metrics between an image and a reference, summed in double. Every metric that compares pixel by
// pixel requires equal sizes and throws illum::Error otherwise. Non-finite pixels are not skipped: they
// make the result NaN or infinite, which is what a comparison should report.
#pragma once

#include <array>

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

// Per-channel means in double; `overall` is the mean of the three. Zero for an empty image.
ErrorStats channel_means(const Image& image);
// (mean(a) - mean(b)) / mean(b) per channel and for the overall means; the images may differ in size.
// When a reference mean is 0 the entry is 0 if the other mean is 0 too and +-inf otherwise.
ErrorStats relative_mean_difference(const Image& a, const Image& reference);

// Box-filters the image down by an integer factor: each output pixel is the mean of a factor x factor
// block. The width and height must be multiples of factor (throws illum::Error otherwise).
Image downsample(const Image& image, int factor);

} // namespace illum
