// Sampling the unit square in proportion to a bilinear function, as PBR 4th ed. §A.5 ("Sampling Linear and
// Bilinear Functions") defines it: f(x, y) = lerp(y, lerp(x, w00, w10), lerp(x, w01, w11)) with the corner
// weights w = {w00, w10, w01, w11} >= 0. y is drawn from the marginal, linear between w00 + w10 and
// w01 + w11, then x from the conditional, linear between lerp(y, w00, w01) and lerp(y, w10, w11). Each
// linear draw inverts the CDF F(x) = x ((2 - x) a + x b) / (a + b), written as
//   x = u (a + b) / (a + √lerp(u, a², b²)),
// the root of the quadratic that has no cancellation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "illum/math/vector.h"

namespace illum {

// x in [0, 1) with density 2 lerp(x, a, b) / (a + b).
inline float sample_linear(float u, float a, float b) {
    if (u == 0 && a == 0) return 0;
    float x = u * (a + b) / (a + std::sqrt((1 - u) * a * a + u * b * b));
    return std::min(x, 0x1.fffffep-1f);
}

// The u that sample_linear maps to x: the CDF at x.
inline float invert_linear_sample(float x, float a, float b) { return x * (a * (2 - x) + b * x) / (a + b); }

// The density of sample_bilinear at p: 4 f(p) / (w00 + w10 + w01 + w11) (1 when all weights are 0).
inline float bilinear_pdf(Point2f p, const std::array<float, 4>& w) {
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1) return 0;
    float sum = w[0] + w[1] + w[2] + w[3];
    if (sum == 0) return 1;
    return 4 *
           ((1 - p.x) * (1 - p.y) * w[0] + p.x * (1 - p.y) * w[1] + (1 - p.x) * p.y * w[2] +
            p.x * p.y * w[3]) /
           sum;
}

inline Point2f sample_bilinear(Point2f u, const std::array<float, 4>& w) {
    float y = sample_linear(u.y, w[0] + w[1], w[2] + w[3]);
    float x = sample_linear(u.x, (1 - y) * w[0] + y * w[2], (1 - y) * w[1] + y * w[3]);
    return {x, y};
}

// The u that sample_bilinear maps to p.
inline Point2f invert_bilinear_sample(Point2f p, const std::array<float, 4>& w) {
    return {invert_linear_sample(p.x, (1 - p.y) * w[0] + p.y * w[2], (1 - p.y) * w[1] + p.y * w[3]),
            invert_linear_sample(p.y, w[0] + w[1], w[2] + w[3])};
}

} // namespace illum
