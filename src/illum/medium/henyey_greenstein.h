// The Henyey-Greenstein phase function (Henyey & Greenstein 1941, "Diffuse radiation in the galaxy",
// ApJ 93), in terms of the directions of travel before (w) and after (w') scattering:
//   p(cos θ) = (1 - g²) / (4π (1 + g² - 2 g cos θ)^{3/2}),   cos θ = w·w',
// forward-peaked for g > 0, isotropic for g = 0, normalised over the sphere. Sampled exactly by inverting
// its CDF in cos θ (e.g. Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., §11.3.1):
//   cos θ = (1 + g² - ((1 - g²) / (1 - g + 2 g ξ))²) / (2 g).
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/math/frame.h"
#include "illum/math/vector.h"

namespace illum {

struct HenyeyGreenstein {
    float g = 0;

    float p(float cos_theta) const {
        float d = 1 + g * g - 2 * g * cos_theta;
        return (1 - g * g) / (4 * kPi * d * std::sqrt(std::max(d, 1e-12f)));
    }
    // A new direction of travel w' for light travelling along w; its density (per steradian) is p.
    Vector3f sample(Vector3f w, Point2f u, float* pdf) const {
        float c;
        if (std::abs(g) < 1e-3f) {
            c = 1 - 2 * u.x;
        } else {
            float s = (1 - g * g) / (1 - g + 2 * g * u.x);
            c = (1 + g * g - s * s) / (2 * g);
        }
        c = std::clamp(c, -1.0f, 1.0f);
        float sn = std::sqrt(std::max(0.0f, 1 - c * c)), phi = 2 * kPi * u.y;
        *pdf = p(c);
        return Frame::from_z(w).to_world(Vector3f(sn * std::cos(phi), sn * std::sin(phi), c));
    }
};

} // namespace illum
