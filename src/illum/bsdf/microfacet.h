// Microfacet normal distributions with anisotropic roughness (αx, αy): Beckmann and Trowbridge-Reitz
// (GGX), their Smith masking Λ, G1, the height-correlated masking-shadowing G2 and the distribution of
// visible normals, with sampling.
//
// References:
// - Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through Rough Surfaces"
//   (Beckmann and GGX D, Smith G1, the reflection/refraction BSDFs).
// - Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs" (anisotropic Λ,
//   height-correlated G2 = 1 / (1 + Λ(wo) + Λ(wi)), visible normals D_wo(m) = G1(wo) max(0, wo·m) D(m) / cos
//   θo).
// - Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4) (GGX VNDF sampling).
//
// D (with tan² θm (cos² φm / αx² + sin² φm / αy²) = e):
//   Beckmann: D(m) = exp(-e) / (π αx αy cos⁴ θm)
//   GGX:      D(m) = 1 / (π αx αy cos⁴ θm (1 + e)²)
// Λ (with a = 1 / (α(w) tan θ), α(w)² = cos² φ αx² + sin² φ αy²):
//   Beckmann: Λ = (erf(a) - 1) / 2 + exp(-a²) / (2 a sqrt(π))
//   GGX:      Λ = (-1 + sqrt(1 + 1/a²)) / 2
// Sampling: GGX samples its visible normals exactly (Heitz 2018). Beckmann samples D(m) cos θm (the slope
// distribution is a 2D Gaussian, so slopes are α·sqrt(-log(1-u1))·(cos, sin) 2πu2), which is exact but
// not visible-normal: a sampled normal facing away from wo is rejected by the models, and pdf_wm() is
// the density actually used, so estimates stay unbiased.
#pragma once

#include <cmath>
#include <cstdint>

#include "illum/math/frame.h"
#include "illum/math/vector.h"

namespace illum {

enum class MicrofacetType : std::uint8_t { Beckmann, GGX };

class MicrofacetDistribution {
public:
    MicrofacetDistribution() = default;
    MicrofacetDistribution(MicrofacetType type, float alpha_x, float alpha_y)
        : type_(type), ax_(alpha_x), ay_(alpha_y) {}

    MicrofacetType type() const { return type_; }
    float alpha_x() const { return ax_; }
    float alpha_y() const { return ay_; }

    // Normal distribution D(m) [sr^-1], normalised so that ∫ D(m) cos θm dωm = 1.
    float D(Vector3f m) const {
        float c2 = cos2_theta(m);
        if (!(c2 > 0)) return 0;
        float t2 = tan2_theta(m);
        if (std::isinf(t2)) return 0;
        float c4 = c2 * c2;
        float e = t2 * (sqr(cos_phi(m) / ax_) + sqr(sin_phi(m) / ay_));
        if (type_ == MicrofacetType::Beckmann) return std::exp(-e) / (kPi * ax_ * ay_ * c4);
        return 1 / (kPi * ax_ * ay_ * c4 * sqr(1 + e));
    }

    // Smith Λ(w) for the direction w (either hemisphere).
    float Lambda(Vector3f w) const {
        float t2 = tan2_theta(w);
        if (std::isinf(t2) || std::isnan(t2)) return 1e30f;
        float alpha2 = sqr(cos_phi(w) * ax_) + sqr(sin_phi(w) * ay_);
        if (type_ == MicrofacetType::GGX) return (std::sqrt(1 + alpha2 * t2) - 1) / 2;
        float a2t2 = alpha2 * t2;
        if (!(a2t2 > 0)) return 0;
        float a = 1 / std::sqrt(a2t2);
        if (a > 8) return 0; // Λ < 1e-29
        return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
    }
    float G1(Vector3f w) const { return 1 / (1 + Lambda(w)); }
    // Height-correlated masking-shadowing.
    float G(Vector3f wo, Vector3f wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }

    // Visible normal distribution D_w(m) = G1(w) max(0, w·m) D(m) / |cos θw| (w flipped to +z).
    float D_visible(Vector3f w, Vector3f m) const {
        float c = abs_cos_theta(w);
        if (c == 0) return 0;
        Vector3f wf = w.z < 0 ? -w : w;
        return G1(w) * std::max(0.0f, dot(wf, m)) * D(m) / c;
    }

    // Density of sample_wm's normals: D_w(m) for GGX, D(m) cos θm for Beckmann. m is on +z.
    float pdf_wm(Vector3f w, Vector3f m) const {
        if (type_ == MicrofacetType::GGX) return D_visible(w, m);
        return D(m) * abs_cos_theta(m);
    }

    // Samples a microfacet normal on +z seen from w (w is flipped to +z first).
    Vector3f sample_wm(Vector3f w, Point2f u) const {
        if (type_ == MicrofacetType::Beckmann) {
            float r = std::sqrt(-std::log1p(-std::min(u.x, 0.99999994f)));
            float phi = 2 * kPi * u.y;
            float sx = ax_ * r * std::cos(phi), sy = ay_ * r * std::sin(phi);
            return normalize(Vector3f(-sx, -sy, 1));
        }
        // Heitz 2018, listing 1: stretch the view direction, sample the projected hemisphere, unstretch.
        if (w.z < 0) w = -w;
        Vector3f wh = normalize(Vector3f(ax_ * w.x, ay_ * w.y, w.z));
        float len2 = wh.x * wh.x + wh.y * wh.y;
        Vector3f t1 = len2 > 0 ? Vector3f(-wh.y, wh.x, 0) / std::sqrt(len2) : Vector3f(1, 0, 0);
        Vector3f t2 = cross(wh, t1);
        float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
        float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
        float s = 0.5f * (1 + wh.z);
        p2 = (1 - s) * safe_sqrt(1 - p1 * p1) + s * p2;
        Vector3f nh = t1 * p1 + t2 * p2 + wh * safe_sqrt(1 - p1 * p1 - p2 * p2);
        return normalize(Vector3f(ax_ * nh.x, ay_ * nh.y, std::max(1e-6f, nh.z)));
    }

private:
    MicrofacetType type_ = MicrofacetType::GGX;
    float ax_ = 0.3f, ay_ = 0.3f;
};

// Refraction of w about the normal n (either side) with relative index eta = n_inside / n_outside,
// inside being the side opposite to n. Returns false on total internal reflection; *etap is the index
// ratio n_t / n_i actually used.
inline bool refract(Vector3f w, Vector3f n, float eta, float* etap, Vector3f* wt) {
    float cos_i = dot(n, w);
    if (cos_i < 0) {
        eta = 1 / eta;
        cos_i = -cos_i;
        n = -n;
    }
    float sin2_i = std::max(0.0f, 1 - cos_i * cos_i);
    float sin2_t = sin2_i / (eta * eta);
    if (sin2_t >= 1) return false;
    float cos_t = std::sqrt(1 - sin2_t);
    *wt = -w / eta + n * (cos_i / eta - cos_t);
    if (etap) *etap = eta;
    return true;
}

} // namespace illum

namespace illum {

// The V-cavity (V-groove) shadowing-masking term of Torrance & Sparrow 1967 in the closed form of
// Blinn 1977 and Cook & Torrance 1982 (eq. 6 of the latter), for wo, wi and the half vector h on +z:
//   G = min(1, 2 (n·h)(n·wo) / (wo·h), 2 (n·h)(n·wi) / (wo·h)).
inline float vcavity_G(Vector3f wo, Vector3f wi, Vector3f h) {
    float oh = std::abs(dot(wo, h));
    if (oh == 0) return 0;
    float nh = std::abs(h.z);
    return std::min(1.0f, std::min(2 * nh * std::abs(wo.z) / oh, 2 * nh * std::abs(wi.z) / oh));
}

// Picks between a diffuse and a specular lobe with probabilities proportional to their mean weights.
inline float specular_lobe_probability(SampledSpectrum kd, SampledSpectrum ks) {
    float d = kd.average(), s = ks.average();
    return d + s > 0 ? s / (d + s) : 0.0f;
}

} // namespace illum
