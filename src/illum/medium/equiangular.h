// Equiangular sampling of a distance along a ray towards a point light (Kulla & Fajardo 2012, "Importance
// Sampling Techniques for Path Tracing in Participating Media", §3): for the ray o + t d (unit d) over
// t in [a, b] and a light at c, with Δ = (c - o)·d and D the light's distance from the line,
//   p(t) = D / ((θ_b - θ_a) (D² + (t - Δ)²)),  θ = atan((t - Δ) / D),
// proportional to the 1/r² falloff of the light's irradiance along the ray, so the single scattering of a
// point or spot light is sampled where it is bright instead of where the medium is likely to scatter.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "illum/math/fast_trig.h"
#include "illum/math/vector.h"

namespace illum {

class Equiangular {
public:
    // Nothing when the light lies on the ray's line or the interval is empty.
    static std::optional<Equiangular> make(Point3f o, Vector3f d, float a, float b, Point3f c) {
        Equiangular e;
        e.delta_ = dot(c - o, d);
        e.d_ = length(c - (o + d * e.delta_));
        if (!(e.d_ > 1e-7f) || !(b > a)) return std::nullopt;
        e.theta_a_ = fast_atan((a - e.delta_) / e.d_);
        // (just below π/2 as a float, so that tan stays positive)
        e.theta_b_ = std::isinf(b) ? kBelowHalfPi : fast_atan((b - e.delta_) / e.d_);
        if (!(e.theta_b_ > e.theta_a_)) return std::nullopt;
        e.a_ = a;
        e.b_ = b;
        return e;
    }
    float sample(float u, float* pdf) const {
        float theta = theta_a_ + u * (theta_b_ - theta_a_);
        float t = std::clamp(delta_ + d_ * fast_tan(theta), a_, b_);
        *pdf = this->pdf(t);
        return t;
    }
    float pdf(float t) const {
        if (t < a_ || t > b_) return 0;
        float x = t - delta_;
        return d_ / ((theta_b_ - theta_a_) * (d_ * d_ + x * x));
    }

private:
    static constexpr float kBelowHalfPi = 1.57079625129699707f; // the float just below π/2
    float delta_ = 0, d_ = 0, theta_a_ = 0, theta_b_ = 0, a_ = 0, b_ = 0;
};

} // namespace illum
