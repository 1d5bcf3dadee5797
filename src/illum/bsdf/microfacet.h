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
// - Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4) (GGX VNDF), sampled by
//   Dupuy & Benyoub 2023, "Sampling Visible GGX Normals with Spherical Caps", CGF 42(8).
//
// D (with tan² θm (cos² φm / αx² + sin² φm / αy²) = e):
//   Beckmann: D(m) = exp(-e) / (π αx αy cos⁴ θm)
//   GGX:      D(m) = 1 / (π αx αy cos⁴ θm (1 + e)²)
// Λ (with a = 1 / (α(w) tan θ), α(w)² = cos² φ αx² + sin² φ αy²):
//   Beckmann: Λ = (erf(a) - 1) / 2 + exp(-a²) / (2 a sqrt(π))
//   GGX:      Λ = (-1 + sqrt(1 + 1/a²)) / 2
// Sampling: GGX samples its visible normals exactly (Heitz 2018, by spherical caps). Beckmann samples
// D(m) cos θm (the slope distribution is a 2D Gaussian, so slopes are α·sqrt(-log(1-u1))·(cos, sin) 2πu2),
// which is exact but not visible-normal: a sampled normal facing away from wo is rejected by the models,
// and pdf_wm() is the density actually used, so estimates stay unbiased.
#pragma once

#include <cmath>
#include <cstdint>

#include "illum/math/fast_trig.h"
#include "illum/math/frame.h"
#include "illum/math/vector.h"

namespace illum {

enum class MicrofacetType : std::uint8_t { Beckmann, GGX };

class MicrofacetDistribution {
public:
    MicrofacetDistribution() = default;
    MicrofacetDistribution(MicrofacetType type, float alpha_x, float alpha_y)
        : type_(type), ax_(alpha_x), ay_(alpha_y), inv_ax2_(1 / (alpha_x * alpha_x)),
          inv_ay2_(1 / (alpha_y * alpha_y)), inv_pi_axay_(1 / (kPi * alpha_x * alpha_y)) {}

    MicrofacetType type() const { return type_; }
    float alpha_x() const { return ax_; }
    float alpha_y() const { return ay_; }

    // Normal distribution D(m) [sr^-1], normalised so that ∫ D(m) cos θm dωm = 1. For a unit m,
    // tan² θm cos² φm = x²/z² and tan² θm sin² φm = y²/z², so e = (x²/αx² + y²/αy²) / z² and
    // cos⁴ θm (1 + e)² = (x²/αx² + y²/αy² + z²)²: no trigonometry and no square root.
    float D(Vector3f m) const {
        float z2 = m.z * m.z;
        if (!(z2 > 0)) return 0;
        float s = m.x * m.x * inv_ax2_ + m.y * m.y * inv_ay2_; // e z²
        if (type_ == MicrofacetType::Beckmann) {
            float e = s / z2;
            if (std::isinf(e) || !(z2 * z2 > 0)) return 0;
            return std::exp(-e) * inv_pi_axay_ / (z2 * z2);
        }
        return inv_pi_axay_ / sqr(s + z2);
    }

    // Smith Λ(w) for the direction w (either hemisphere). α(w)² tan² θ = (x² αx² + y² αy²) / z² for a
    // unit w.
    float Lambda(Vector3f w) const {
        float z2 = w.z * w.z;
        if (!(z2 > 0)) return 1e30f;
        float a2t2 = (sqr(w.x * ax_) + sqr(w.y * ay_)) / z2;
        if (std::isinf(a2t2) || std::isnan(a2t2)) return 1e30f;
        // GGX: (sqrt(1 + a2t2) - 1) / 2, written without the cancellation at small a2t2.
        if (type_ == MicrofacetType::GGX) return a2t2 / (2 * (std::sqrt(1 + a2t2) + 1));
        if (!(a2t2 > 0)) return 0;
        float a = 1 / std::sqrt(a2t2);
        if (a > 8) return 0; // Λ < 1e-29
        return (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
    }
    float G1(Vector3f w) const { return 1 / (1 + Lambda(w)); }
    // Height-correlated masking-shadowing.
    float G(Vector3f wo, Vector3f wi) const { return 1 / (1 + Lambda(wo) + Lambda(wi)); }

    // Visible normal distribution D_w(m) = G1(w) max(0, w·m) D(m) / |cos θw| (w flipped to +z), with
    // G1 = 1 / (1 + Λ(w)); the second form takes D(m) and Λ(w) at hand (a model that also evaluates f has
    // them).
    float D_visible(Vector3f w, Vector3f m) const { return D_visible(w, m, D(m), Lambda(w)); }
    float D_visible(Vector3f w, Vector3f m, float d_m, float lambda_w) const {
        float c = abs_cos_theta(w);
        if (c == 0) return 0;
        Vector3f wf = w.z < 0 ? -w : w;
        return std::max(0.0f, dot(wf, m)) * d_m / ((1 + lambda_w) * c);
    }

    // Density of sample_wm's normals: D_w(m) for GGX, D(m) cos θm for Beckmann. m is on +z.
    float pdf_wm(Vector3f w, Vector3f m) const {
        return pdf_wm(w, m, D(m), type_ == MicrofacetType::GGX ? Lambda(w) : 0.0f);
    }
    // The same with D(m) and Λ(w) at hand (Λ is not read for Beckmann).
    float pdf_wm(Vector3f w, Vector3f m, float d_m, float lambda_w) const {
        if (type_ == MicrofacetType::GGX) return D_visible(w, m, d_m, lambda_w);
        return d_m * abs_cos_theta(m);
    }

    // Samples a microfacet normal on +z seen from w (w is flipped to +z first).
    Vector3f sample_wm(Vector3f w, Point2f u) const {
        if (type_ == MicrofacetType::Beckmann) {
            float r = std::sqrt(-std::log1p(-std::min(u.x, 0.99999994f)));
            float phi = 2 * kPi * u.y;
            float sx = ax_ * r * std::cos(phi), sy = ay_ * r * std::sin(phi);
            return normalize(Vector3f(-sx, -sy, 1));
        }
        // Visible normals by spherical caps (Dupuy & Benyoub 2023, "Sampling Visible GGX Normals with
        // Spherical Caps"): in the stretched configuration the visible normals of the view wh
        // are h = c + wh with c uniform on the spherical cap z > -wh.z of the unit sphere; unstretch h.
        // The same density as Heitz 2018's projected-disk construction, without its tangent frame.
        if (w.z < 0) w = -w;
        Vector3f wh = normalize(Vector3f(ax_ * w.x, ay_ * w.y, w.z));
        float sin_phi, cos_phi;
        fast_sincos_2pi(u.x, &sin_phi, &cos_phi);
        float z = std::fma(1 - u.y, 1 + wh.z, -wh.z);
        float sin_theta = safe_sqrt(1 - z * z);
        Vector3f h(sin_theta * cos_phi + wh.x, sin_theta * sin_phi + wh.y, z + wh.z);
        return normalize(Vector3f(ax_ * h.x, ay_ * h.y, std::max(1e-6f, h.z)));
    }

private:
    MicrofacetType type_ = MicrofacetType::GGX;
    float ax_ = 0.3f, ay_ = 0.3f;
    // 1/αx², 1/αy² and 1/(π αx αy), for D.
    float inv_ax2_ = 1 / (0.3f * 0.3f), inv_ay2_ = 1 / (0.3f * 0.3f), inv_pi_axay_ = 1 / (kPi * 0.3f * 0.3f);
};

// Refraction of w about the normal n (either side) with relative index eta = n_inside / n_outside,
// inside being the side opposite to n. Returns false on total internal reflection; *etap is the index
// ratio n_t / n_i actually used.
inline bool refract(Vector3f w, Vector3f n, float eta, float* etap, Vector3f* wt) {
    float cos_i = dot(n, w);
    // One division: the relative index n_t / n_i used and its inverse.
    const float inv = 1 / eta;
    float inv_eta = inv;
    if (cos_i < 0) {
        inv_eta = eta;
        eta = inv;
        cos_i = -cos_i;
        n = -n;
    }
    float sin2_i = std::max(0.0f, 1 - cos_i * cos_i);
    float sin2_t = sin2_i * (inv_eta * inv_eta);
    if (sin2_t >= 1) return false;
    float cos_t = std::sqrt(1 - sin2_t);
    *wt = -w * inv_eta + n * (cos_i * inv_eta - cos_t);
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
