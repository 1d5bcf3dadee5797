// Fresnel reflectance: the exact unpolarised equations for dielectrics and for conductors with a complex
// index of refraction, and Schlick's approximation.
//
// Exact (Born & Wolf, "Principles of Optics", §1.5; Hecht, "Optics", §4.6): with η = n_t/n_i, cos θi,
// sin² θt = sin² θi / η², the amplitude ratios
//   r_par  = (η cos θi - cos θt) / (η cos θi + cos θt),   r_perp = (cos θi - η cos θt) / (cos θi + η cos θt)
// and F = (|r_par|² + |r_perp|²) / 2 for unpolarised light. For a conductor η = n + ik is complex and the
// same equations hold with complex cos θt = sqrt(1 - sin² θt).
// Schlick (1994, "An Inexpensive BRDF Model for Physically-based Rendering", eq. 24):
//   F(θ) = F0 + (1 - F0)(1 - cos θ)^5.
#pragma once

#include <complex>
#include <cstdint>

#include "illum/math/vector.h"
#include "illum/radiometry/color.h"
#include "illum/radiometry/sampled_spectrum.h"

namespace illum {

// Exact unpolarised Fresnel reflectance of a dielectric interface. eta = n_inside / n_outside, the
// inside being -z; cos_i < 0 means the light arrives from inside (then η is inverted). Total internal
// reflection gives 1.
//
// Written with g = η cos θt = sqrt(η² − 1 + cos² θi) (Walter et al. 2007, "Microfacet Models for
// Refraction through Rough Surfaces", eq. 22): r_perp = (c − g)/(c + g), r_par = (η² c − g)/(η² c + g)
// with c = cos θi, one square root and two independent divisions. From inside (relative index 1/η) both
// ratios are scaled by η: G = sqrt(1 − η² sin² θi), r_perp = (η c − G)/(η c + G),
// r_par = (c − η G)/(c + η G).
inline float fresnel_dielectric(float cos_i, float eta) {
    cos_i = std::clamp(cos_i, -1.0f, 1.0f);
    float a, b, p, q; // r_perp = a / b, r_par = p / q
    if (cos_i >= 0) {
        const float g2 = eta * eta - 1 + cos_i * cos_i;
        if (g2 <= 0) return 1;
        const float g = std::sqrt(g2), e2c = eta * eta * cos_i;
        a = cos_i - g;
        b = cos_i + g;
        p = e2c - g;
        q = e2c + g;
    } else {
        const float c = -cos_i;
        const float g2 = 1 - eta * eta * (1 - c * c);
        if (g2 <= 0) return 1;
        const float g = std::sqrt(g2), ec = eta * c, eg = eta * g;
        a = ec - g;
        b = ec + g;
        p = c - eg;
        q = c + eg;
    }
    return 0.5f * (sqr(a / b) + sqr(p / q));
}

// Exact unpolarised Fresnel reflectance of a conductor of complex relative index eta + i k, for light
// arriving from outside (|cos_i| is used). With k = 0 and eta >= 1 it equals fresnel_dielectric.
inline float fresnel_complex(float cos_i, std::complex<float> eta_k) {
    // The real closed form for an absorbing medium (Born & Wolf, Principles of Optics, §14.2): with
    // t0 = η² − k² − sin²θ and a² + b² = sqrt(t0² + 4η²k²), a² = (a² + b² + t0)/2,
    //   R_s = (a² + b² − 2a cos θ + cos²θ) / (a² + b² + 2a cos θ + cos²θ),
    //   R_p = R_s (cos²θ (a² + b²) − 2a cos θ sin²θ + sin⁴θ) / (cos²θ (a² + b²) + 2a cos θ sin²θ + sin⁴θ),
    // F = (R_s + R_p)/2. Equal to the complex Snell-Fresnel form, without complex division (a library call).
    float eta = eta_k.real(), k = eta_k.imag();
    float c = std::clamp(std::abs(cos_i), 0.0f, 1.0f), c2 = c * c, s2 = 1 - c2;
    float t0 = eta * eta - k * k - s2;
    float a2b2 = std::sqrt(std::max(0.0f, t0 * t0 + 4 * eta * eta * k * k));
    float a = std::sqrt(std::max(0.0f, 0.5f * (a2b2 + t0)));
    float t1 = a2b2 + c2, t2 = 2 * a * c;
    float rs = (t1 - t2) / (t1 + t2);
    float t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    float rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5f * (rs + rp);
}

inline SampledSpectrum fresnel_complex(float cos_i, SampledSpectrum eta, SampledSpectrum k) {
    SampledSpectrum f;
    for (int i = 0; i < kSpectrumSamples; ++i) f[i] = fresnel_complex(cos_i, {eta[i], k[i]});
    return f;
}

// The same for an RGB index (the tools' and tests' RGB mode).
inline Color3 fresnel_complex(float cos_i, Color3 eta, Color3 k) {
    return fresnel_complex(cos_i, SampledSpectrum(eta), SampledSpectrum(k)).rgb();
}

// Schlick's approximation given the reflectance at normal incidence.
inline float fresnel_schlick(float cos_i, float f0) {
    float m = std::clamp(1 - std::abs(cos_i), 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (1 - f0) * (m2 * m2 * m);
}
inline SampledSpectrum fresnel_schlick(float cos_i, SampledSpectrum f0) {
    float m = std::clamp(1 - std::abs(cos_i), 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (SampledSpectrum(1) - f0) * (m2 * m2 * m);
}

// Normal-incidence reflectances: ((η-1)/(η+1))² for a dielectric, ((n-1)² + k²)/((n+1)² + k²) for a
// conductor.
inline float dielectric_f0(float eta) { return sqr((eta - 1) / (eta + 1)); }
inline SampledSpectrum conductor_f0(SampledSpectrum eta, SampledSpectrum k) {
    SampledSpectrum k2 = k * k;
    return ((eta - SampledSpectrum(1)) * (eta - SampledSpectrum(1)) + k2) /
           ((eta + SampledSpectrum(1)) * (eta + SampledSpectrum(1)) + k2);
}

// Schlick for a dielectric seen from either side: from the denser side the angle in the lighter medium
// (the transmitted one) is used, so that the approximation is symmetric and total internal reflection
// gives 1.
inline float fresnel_dielectric_schlick(float cos_i, float eta) {
    float c = std::clamp(cos_i, -1.0f, 1.0f);
    float e = c < 0 ? 1 / eta : eta; // n_t / n_i
    c = std::abs(c);
    if (e < 1) { // leaving the denser medium: use cos θt
        float sin2_t = (1 - c * c) / (e * e);
        if (sin2_t >= 1) return 1;
        c = std::sqrt(1 - sin2_t);
    }
    return fresnel_schlick(c, dielectric_f0(eta));
}

enum class FresnelMode : std::uint8_t { Exact, Schlick };

// A dielectric interface's Fresnel term, exact or Schlick (value type, 8 bytes).
struct DielectricFresnel {
    float eta = 1.5f;
    FresnelMode mode = FresnelMode::Exact;
    float operator()(float cos_i) const {
        return mode == FresnelMode::Exact ? fresnel_dielectric(cos_i, eta)
                                          : fresnel_dielectric_schlick(cos_i, eta);
    }
};

// A conductor's (or, with k = 0, an opaque dielectric's) Fresnel term, exact or Schlick. Light always
// arrives from outside.
struct Fresnel {
    SampledSpectrum eta{1.5f}, k{0};
    FresnelMode mode = FresnelMode::Exact;
    SampledSpectrum f0() const { return conductor_f0(eta, k); }
    SampledSpectrum operator()(float cos_i) const {
        if (mode == FresnelMode::Schlick) return fresnel_schlick(cos_i, f0());
        return fresnel_complex(cos_i, eta, k);
    }
};

} // namespace illum
