// Hair fibre scattering: Chiang, Bitterli, Tappan, Burley 2016, "A Practical and Controllable Hair and Fur
// Model for Production Path Tracing" (CGF 35(2)), with the longitudinal function of d'Eon, Francois,
// Hill, Letteri, Aubry 2011, "An Energy-Conserving Hair Reflectance Model", as pbrt-v4's HairBxDF uses them.
//
// The fibre is a dielectric cylinder (index η) with an absorbing interior (σ_a per unit of the fibre's
// radius). In the local frame x runs along the fibre (the curve's dp/du), so for a direction w:
// sin θ = w.x (longitudinal angle), φ = atan2(w.z, w.y) (azimuth around the fibre). h ∈ [-1, 1] is where
// the ray met the fibre across its width (sin γ_o = h). The scattered radiance is a sum over paths p = 0
// (R), 1 (TT), 2 (TRT) and p ≥ 3 (the rest, azimuthally uniform):
//     S(wo, wi) = Σ_p M_p(θo, θi) A_p(θo, h) N_p(φ)              (Chiang eq. 1)
// and f = S / |cos θ_i| with cos θ_i = wi.z (the shading normal's cosine, which the integrator multiplies
// back), as pbrt-v4 does. Each factor:
//   M_p  d'Eon et al. eq. 7: exp(-sin θi sin θo / v) I0(cos θi cos θo / v) / (2 v sinh(1/v)), and for
//        v <= 0.1 its logarithmic form with log I0 (eq. 9 of d'Eon; pbrt-v4 §9.9.3) to avoid overflow;
//        θo tilted by the cuticle scales: θo - 2α (R), θo + α (TT), θo + 4α (TRT) (Chiang §4.1).
//   A_p  Fresnel f at cos θo cos γo and the transmittance T = exp(-σ_a 2 cos γt / cos θt) through the
//        fibre: A_0 = f, A_1 = (1-f)² T, A_2 = A_1 T f, A_3 = A_2 f T / (1 - T f) (Chiang eq. 3-6).
//   N_p  a trimmed logistic of scale s in Δφ - Φ(p), Φ(p) = 2p γt - 2γo + pπ (Chiang eq. 7-9); N_3 = 1/2π.
// Roughness: v = (0.726 β_m + 0.812 β_m² + 3.7 β_m²⁰)² (R), v/4 (TT), 4v (TRT and after) (Chiang eq. 7);
// s = sqrt(π/8) (0.265 β_n + 1.194 β_n² + 5.372 β_n²²) (Chiang eq. 8).
// Sampling picks p by A_p's luminance share, θi from M_p exactly (d'Eon's sampling of the spherical
// Gaussian), Δφ from the trimmed logistic; pdf() is the matching mixture.
//
// The model is not reciprocal in the usual sense (h and the tilts are defined from wo's side); pbrt-v4
// disables its reciprocity test (src/pbrt/bsdfs_test.cpp), and the audit skips it (registry.cpp).
// Directions on the other side of the shading plane are flagged transmission (light does pass through
// the fibre), with η = 1 for the path (the fibre's refraction is inside the model).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "illum/bsdf/bxdf.h"
#include "illum/bsdf/common.h"
#include "illum/bsdf/fresnel.h"

namespace illum {

namespace hair_detail {

inline constexpr int kPMax = 3;
inline constexpr float k2Pi = 2 * kPi;

// Modified Bessel function of the first kind, order 0, by its power series Σ (x²/4)^i / (i!)², summed
// until the terms stop mattering (at most 64 terms: x <= 10 where it is used needs about 30).
inline float bessel_i0(float x) {
    double q = double(x) * x / 4, term = 1, sum = 1;
    for (int i = 1; i < 64; ++i) {
        term *= q / (double(i) * i);
        sum += term;
        if (term < 1e-9 * sum) break;
    }
    return float(sum);
}

// log I0(x); for large x its asymptotic expansion I0(x) ~ e^x / sqrt(2πx) (1 + 1/(8x) + 9/(128x²) +
// 225/(3072x³)) (Abramowitz & Stegun 9.7.1). pbrt-v4's LogI0 uses x + ½ (log(1/(2πx)) + 1/(8x)), which
// halves the 1/(8x) term: its narrow lobes (v < 0.05) then integrate to 0.998, not 1.
inline float log_bessel_i0(float x) {
    if (x > 12) {
        float r = 1 / x;
        return x - 0.5f * std::log(2 * kPi * x) +
               std::log1p(r * (0.125f + r * (0.0703125f + r * 0.0732421875f)));
    }
    return std::log(bessel_i0(x));
}

// d'Eon et al. 2011 eq. 7, and for v <= 0.1 its logarithm, with 1/(2v sinh(1/v)) = e^(-1/v) / v to within
// e^(-2/v) < 2·10⁻⁹ (pbrt-v4 writes ln 2 as 0.6931 there).
inline float longitudinal(float cos_i, float cos_o, float sin_i, float sin_o, float v) {
    float a = cos_i * cos_o / v, b = sin_i * sin_o / v;
    if (v <= 0.1f) return std::exp(log_bessel_i0(a) - b - 1 / v - std::log(v));
    return std::exp(-b) * bessel_i0(a) / (std::sinh(1 / v) * 2 * v);
}

// The logistic distribution of scale s, its CDF, and its restriction to [a, b].
inline float logistic(float x, float s) {
    x = std::abs(x);
    float e = std::exp(-x / s);
    return e / (s * sqr(1 + e));
}
inline float logistic_cdf(float x, float s) { return 1 / (1 + std::exp(-x / s)); }
inline float trimmed_logistic(float x, float s, float a, float b) {
    return logistic(x, s) / (logistic_cdf(b, s) - logistic_cdf(a, s));
}
// 1 / (CDF(π) - CDF(-π)): the trimmed logistic's normalisation over [-π, π], fixed per BxDF.
inline float trimmed_logistic_norm(float s) { return 1 / (logistic_cdf(kPi, s) - logistic_cdf(-kPi, s)); }
// Inverts the trimmed logistic's CDF.
inline float sample_trimmed_logistic(float u, float s, float a, float b) {
    float k = logistic_cdf(b, s) - logistic_cdf(a, s);
    float x = -s * std::log(1 / (u * k + logistic_cdf(a, s)) - 1);
    return std::clamp(x, a, b);
}

// Chiang eq. 9: the azimuthal deflection of path p.
inline float deflection(int p, float gamma_o, float gamma_t) {
    return 2 * p * gamma_t - 2 * gamma_o + p * kPi;
}

// N_p: the trimmed logistic around Φ(p), Δφ wrapped to [-π, π]; norm = trimmed_logistic_norm(s).
inline float azimuthal(float phi, int p, float s, float norm, float gamma_o, float gamma_t) {
    float d = phi - deflection(p, gamma_o, gamma_t);
    d = std::remainder(d, k2Pi);
    return logistic(d, s) * norm;
}

} // namespace hair_detail

class HairBxDF final : public BxDF {
public:
    static constexpr int kPMax = hair_detail::kPMax;

    // h ∈ [-1, 1], eta > 0, sigma_a >= 0 (per unit radius), beta_m, beta_n ∈ [0, 1] (pbrt-v4's material
    // clamps them to [0.01, 1]), alpha the cuticle tilt in degrees.
    HairBxDF(float h, float eta, SampledSpectrum sigma_a, float beta_m, float beta_n, float alpha_deg)
        : h_(h), eta_(eta), sigma_a_(sigma_a) {
        ILLUM_REQUIRE(h >= -1 && h <= 1, "hair", "h must lie in [-1, 1], got " + bsdf_detail::str(h));
        ILLUM_REQUIRE(eta > 0 && std::isfinite(eta), "hair", "eta must be positive");
        ILLUM_REQUIRE(beta_m >= 0 && beta_m <= 1, "hair", "beta_m must lie in [0, 1]");
        ILLUM_REQUIRE(beta_n >= 0 && beta_n <= 1, "hair", "beta_n must lie in [0, 1]");
        ILLUM_REQUIRE(!sigma_a.has_negative() && sigma_a.is_finite(), "hair", "sigma_a must be >= 0");
        ILLUM_REQUIRE(std::isfinite(alpha_deg), "hair", "alpha must be finite");
        // Chiang eq. 7 (β_m 0 would make v 0: a lobe of zero width, kept just above so M_p stays finite).
        v_[0] = std::max(sqr(0.726f * beta_m + 0.812f * sqr(beta_m) + 3.7f * std::pow(beta_m, 20.0f)), 1e-5f);
        v_[1] = 0.25f * v_[0];
        v_[2] = 4 * v_[0];
        v_[3] = v_[2];
        // Chiang eq. 8, with sqrt(π/8) turning the Gaussian's width into the logistic's scale.
        s_ = std::max(0.626657069f *
                          (0.265f * beta_n + 1.194f * sqr(beta_n) + 5.372f * std::pow(beta_n, 22.0f)),
                      1e-5f);
        norm_ = hair_detail::trimmed_logistic_norm(s_);
        // sin and cos of 2^k α for k = 0, 1, 2 (the tilts α, 2α, 4α).
        float a = alpha_deg * (kPi / 180);
        sin2k_alpha_[0] = std::sin(a);
        cos2k_alpha_[0] = safe_sqrt(1 - sqr(sin2k_alpha_[0]));
        for (int i = 1; i < 3; ++i) {
            sin2k_alpha_[i] = 2 * cos2k_alpha_[i - 1] * sin2k_alpha_[i - 1];
            cos2k_alpha_[i] = sqr(cos2k_alpha_[i - 1]) - sqr(sin2k_alpha_[i - 1]);
        }
    }

    std::uint8_t flags() const override { return kGlossy | kReflection | kTransmission; }

    Bsdf3 f(Vector3f wo, Vector3f wi, TransportMode) const override {
        using namespace hair_detail;
        Geometry g = geometry(wo);
        float sin_i = wi.x, cos_i = safe_sqrt(1 - sqr(sin_i));
        float phi = std::atan2(wi.z, wi.y) - g.phi_o;
        std::array<SampledSpectrum, kPMax + 1> ap = attenuation(g);
        SampledSpectrum sum;
        for (int p = 0; p < kPMax; ++p) {
            auto [sin_op, cos_op] = tilted(p, g);
            sum += ap[std::size_t(p)] * (longitudinal(cos_i, cos_op, sin_i, sin_op, v_[p]) *
                                         azimuthal(phi, p, s_, norm_, g.gamma_o, g.gamma_t));
        }
        sum += ap[kPMax] * (longitudinal(cos_i, g.cos_o, sin_i, g.sin_o, v_[kPMax]) / k2Pi);
        if (std::abs(wi.z) > 0) sum /= std::abs(wi.z);
        return Bsdf3(sum);
    }

    std::optional<BSDFSample> sample(Vector3f wo, float uc, Point2f u, TransportMode mode) const override {
        using namespace hair_detail;
        Geometry g = geometry(wo);
        std::array<float, kPMax + 1> ap_pdf = attenuation_pdf(g);
        // Choose p by A_p's share, then reuse uc (rescaled to the chosen interval) for Δφ.
        int p = 0;
        float cdf = 0;
        for (; p < kPMax; ++p) {
            if (uc < cdf + ap_pdf[std::size_t(p)]) break;
            cdf += ap_pdf[std::size_t(p)];
        }
        float width = ap_pdf[std::size_t(p)];
        if (!(width > 0)) return std::nullopt;
        uc = std::min((uc - cdf) / width, 0x1.fffffep-1f);
        auto [sin_op, cos_op] = tilted(p, g);
        // θi from M_p: d'Eon et al. 2011's sampling of the spherical Gaussian around -θo'.
        float u0 = std::max(u.x, 1e-5f);
        float cos_theta = 1 + v_[p] * std::log(u0 + (1 - u0) * std::exp(-2 / v_[p]));
        float sin_theta = safe_sqrt(1 - sqr(cos_theta));
        float cos_phi = std::cos(k2Pi * u.y);
        float sin_i = std::clamp(-cos_theta * sin_op + sin_theta * cos_phi * cos_op, -1.0f, 1.0f);
        float cos_i = safe_sqrt(1 - sqr(sin_i));
        float dphi = p < kPMax
                         ? deflection(p, g.gamma_o, g.gamma_t) + sample_trimmed_logistic(uc, s_, -kPi, kPi)
                         : k2Pi * uc;
        float phi_i = g.phi_o + dphi;
        Vector3f wi(sin_i, cos_i * std::cos(phi_i), cos_i * std::sin(phi_i));
        SolidAnglePdf density = pdf(wo, wi, mode);
        if (!(density.value > 0)) return std::nullopt;
        std::uint8_t side = same_hemisphere(wo, wi) ? kGlossyReflection : kGlossyTransmission;
        return BSDFSample{wi, f(wo, wi, mode), density, side};
    }

    SolidAnglePdf pdf(Vector3f wo, Vector3f wi, TransportMode) const override {
        using namespace hair_detail;
        Geometry g = geometry(wo);
        float sin_i = wi.x, cos_i = safe_sqrt(1 - sqr(sin_i));
        float phi = std::atan2(wi.z, wi.y) - g.phi_o;
        std::array<float, kPMax + 1> ap_pdf = attenuation_pdf(g);
        float sum = 0;
        for (int p = 0; p < kPMax; ++p) {
            auto [sin_op, cos_op] = tilted(p, g);
            sum += ap_pdf[std::size_t(p)] * longitudinal(cos_i, cos_op, sin_i, sin_op, v_[p]) *
                   azimuthal(phi, p, s_, norm_, g.gamma_o, g.gamma_t);
        }
        sum += ap_pdf[kPMax] * longitudinal(cos_i, g.cos_o, sin_i, g.sin_o, v_[kPMax]) / k2Pi;
        return SolidAnglePdf(sum);
    }

    // σ_a of a fibre with these concentrations of eumelanin and pheomelanin (Chiang §5.1: the two
    // pigments' absorption, per unit concentration, in linear sRGB).
    static Color3 sigma_a_from_concentration(float eumelanin, float pheomelanin) {
        return Color3(0.419f, 0.697f, 1.37f) * eumelanin + Color3(0.187f, 0.4f, 1.05f) * pheomelanin;
    }
    // σ_a that gives a fibre of azimuthal roughness β_n the colour c after multiple scattering (Chiang
    // eq. 10: σ_a = (ln c / (5.969 - 0.215 β_n + 2.532 β_n² - 10.73 β_n³ + 5.574 β_n⁴ + 0.245 β_n⁵))²).
    static SampledSpectrum sigma_a_from_reflectance(SampledSpectrum c, float beta_n) {
        float d = 5.969f - 0.215f * beta_n + 2.532f * sqr(beta_n) - 10.73f * std::pow(beta_n, 3.0f) +
                  5.574f * std::pow(beta_n, 4.0f) + 0.245f * std::pow(beta_n, 5.0f);
        SampledSpectrum s;
        for (int i = 0; i < kSpectrumSamples; ++i) s[i] = sqr(std::log(std::max(c[i], 1e-6f)) / d);
        return s;
    }

private:
    // What f, sample and pdf share about wo and the refracted ray (Chiang §3; Snell's law for the
    // modified index η' = sqrt(η² - sin² θo) / cos θo of the projected problem, Marschner et al. 2003).
    struct Geometry {
        float sin_o, cos_o, phi_o, gamma_o, gamma_t;
        SampledSpectrum transmittance; // T = exp(-σ_a 2 cos γt / cos θt)
    };
    Geometry geometry(Vector3f wo) const {
        Geometry g;
        g.sin_o = std::clamp(wo.x, -1.0f, 1.0f);
        g.cos_o = safe_sqrt(1 - sqr(g.sin_o));
        g.phi_o = std::atan2(wo.z, wo.y);
        g.gamma_o = safe_asin(h_);
        float sin_t = g.sin_o / eta_, cos_t = safe_sqrt(1 - sqr(sin_t));
        float eta_p = safe_sqrt(sqr(eta_) - sqr(g.sin_o)) / std::max(g.cos_o, 1e-7f);
        float sin_gt = std::clamp(h_ / eta_p, -1.0f, 1.0f), cos_gt = safe_sqrt(1 - sqr(sin_gt));
        g.gamma_t = std::asin(sin_gt);
        g.transmittance = exp(-sigma_a_ * (2 * cos_gt / std::max(cos_t, 1e-7f)));
        return g;
    }
    // A_p (Chiang eq. 3-6), with the Fresnel reflectance at the angle cos θo cos γo.
    std::array<SampledSpectrum, kPMax + 1> attenuation(const Geometry& g) const {
        std::array<SampledSpectrum, kPMax + 1> ap;
        float cos_gamma_o = safe_sqrt(1 - sqr(h_));
        float f = fresnel_dielectric(g.cos_o * cos_gamma_o, eta_);
        const SampledSpectrum& t = g.transmittance;
        ap[0] = SampledSpectrum(f);
        ap[1] = sqr(1 - f) * t;
        ap[2] = ap[1] * t * f;
        SampledSpectrum rest = SampledSpectrum(1.0f) - t * f;
        for (int i = 0; i < kSpectrumSamples; ++i)
            ap[3][i] = rest[i] > 0 ? ap[2][i] * f * t[i] / rest[i] : 0.0f;
        return ap;
    }
    // The probability of sampling each p: A_p's average over the channels, normalised.
    std::array<float, kPMax + 1> attenuation_pdf(const Geometry& g) const {
        std::array<SampledSpectrum, kPMax + 1> ap = attenuation(g);
        std::array<float, kPMax + 1> pdf;
        float total = 0;
        for (int p = 0; p <= kPMax; ++p) total += pdf[std::size_t(p)] = ap[std::size_t(p)].average();
        for (float& x : pdf) x = total > 0 ? x / total : 0.0f;
        return pdf;
    }
    // sin θo' and |cos θo'| of θo tilted for path p by the cuticle scales (Chiang §4.1): -2α for R, +α for
    // TT, +4α for TRT, none after; |cos| keeps a tilt past the pole meaningful (pbrt-v4 does the same).
    std::pair<float, float> tilted(int p, const Geometry& g) const {
        float s = g.sin_o, c = g.cos_o;
        switch (p) {
        case 0:
            return {s * cos2k_alpha_[1] - c * sin2k_alpha_[1],
                    std::abs(c * cos2k_alpha_[1] + s * sin2k_alpha_[1])};
        case 1:
            return {s * cos2k_alpha_[0] + c * sin2k_alpha_[0],
                    std::abs(c * cos2k_alpha_[0] - s * sin2k_alpha_[0])};
        case 2:
            return {s * cos2k_alpha_[2] + c * sin2k_alpha_[2],
                    std::abs(c * cos2k_alpha_[2] - s * sin2k_alpha_[2])};
        default:
            return {s, c};
        }
    }

    float h_, eta_;
    SampledSpectrum sigma_a_;
    float v_[kPMax + 1];
    float s_, norm_;
    float sin2k_alpha_[3], cos2k_alpha_[3];
};

} // namespace illum
