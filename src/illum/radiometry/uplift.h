// RGB inputs as spectra (spectral mode), as pbrt-v4 uplifts them so that the same scene gives the same
// colours: a reflectance by its sigmoid polynomial (Jakob & Hanika 2019), an unbounded value (an index,
// a scattering coefficient) as 2m times the polynomial of rgb/(2m), m its largest component, and an
// emitter's RGB as that unbounded spectrum times the colour space's illuminant (normalised to luminance
// 1), so (1, 1, 1) is the space's white of luminance 1. In RGB mode each is the identity (a reflectance
// clamped to [0, 1]).
#pragma once

#include <array>
#include <cstdint>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "illum/radiometry/color_space.h"
#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

// One RGB value's spectrum, scale · S(c0 λ² + c1 λ + c2): computed once (a constant parameter) or per hit (a
// texture).
struct UpliftedRgb {
    RGBSigmoidPolynomial poly;
    float scale = 1;
    double operator()(double lambda_nm) const { return scale * poly(float(lambda_nm)); }
};
UpliftedRgb uplift_albedo_poly(Color3 rgb, const RGBColorSpace& cs);    // rgb clamped to [0, 1]
UpliftedRgb uplift_unbounded_poly(Color3 rgb, const RGBColorSpace& cs); // rgb clamped to >= 0

inline SampledSpectrum sample(const UpliftedRgb& u, const SampledWavelengths& w) {
    // A grey's polynomial is the constant c2 (RGBToSpectrumTable::lookup): one sigmoid, the same value.
    if (u.poly.c0 == 0 && u.poly.c1 == 0) return SampledSpectrum(u.scale * u.poly(w.lambda[0]));
    SampledSpectrum s;
#if defined(__SSE2__)
    static_assert(kSpectrumSamples == 4);
    // The four wavelengths at once (every hit of a spectral render uplifts its reflectances): the same
    // operations as RGBSigmoidPolynomial, x = (c0 λ + c1) λ + c2 and S(x) = 1/2 + x / (2 √(1 + x²)), with
    // S = 0 or 1 where |x| ≥ 1e18 (x² would overflow).
    const __m128 l = _mm_loadu_ps(w.lambda);
    const __m128 x =
        _mm_add_ps(_mm_mul_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(u.poly.c0), l), _mm_set1_ps(u.poly.c1)), l),
                   _mm_set1_ps(u.poly.c2));
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 root = _mm_sqrt_ps(_mm_add_ps(one, _mm_mul_ps(x, x)));
    const __m128 sig = _mm_add_ps(_mm_set1_ps(0.5f), _mm_div_ps(x, _mm_mul_ps(_mm_set1_ps(2.0f), root)));
    const __m128 abs_x = _mm_andnot_ps(_mm_set1_ps(-0.0f), x);
    const __m128 finite = _mm_cmplt_ps(abs_x, _mm_set1_ps(1e18f)); // false for NaN too, as the scalar form
    const __m128 limit = _mm_and_ps(_mm_cmpgt_ps(x, _mm_setzero_ps()), one);
    const __m128 v = _mm_or_ps(_mm_and_ps(finite, sig), _mm_andnot_ps(finite, limit));
    _mm_storeu_ps(&s[0], _mm_mul_ps(_mm_set1_ps(u.scale), v));
#else
    for (int i = 0; i < kSpectrumSamples; ++i) s[i] = u.scale * u.poly(w.lambda[i]);
#endif
    return s;
}

inline SampledSpectrum uplift_albedo(Color3 rgb, const SampledWavelengths& w) {
    if (!w.spectral()) return SampledSpectrum(clamp(rgb, 0.0f, 1.0f));
    return sample(uplift_albedo_poly(rgb, *w.color_space), w);
}
inline SampledSpectrum uplift_unbounded(Color3 rgb, const SampledWavelengths& w) {
    if (!w.spectral()) return SampledSpectrum(rgb);
    return sample(uplift_unbounded_poly(rgb, *w.color_space), w);
}
// The colour space's illuminant at the four wavelengths, luminance 1.
SampledSpectrum illuminant_at(const RGBColorSpace& cs, const SampledWavelengths& w);
inline SampledSpectrum uplift_illuminant(Color3 rgb, const SampledWavelengths& w) {
    if (!w.spectral()) return SampledSpectrum(rgb);
    return sample(uplift_unbounded_poly(rgb, *w.color_space), w) * illuminant_at(*w.color_space, w);
}

// One constant RGB value's polynomial in every colour space, computed once (a constant texture or
// parameter), so spectral mode does not look the table up at every hit.
enum class UpliftKind : std::uint8_t { Albedo, Unbounded };
class UpliftCache {
public:
    UpliftCache() = default;
    UpliftCache(Color3 rgb, UpliftKind kind)
        : rgb_(kind == UpliftKind::Albedo ? clamp(rgb, 0.0f, 1.0f) : rgb) {
        for (int i = 0; i < RGBColorSpace::kCount; ++i) {
            const RGBColorSpace& cs = RGBColorSpace::by_index(i);
            poly_[std::size_t(i)] =
                kind == UpliftKind::Albedo ? uplift_albedo_poly(rgb, cs) : uplift_unbounded_poly(rgb, cs);
        }
    }
    SampledSpectrum at(const SampledWavelengths& w) const {
        if (!w.spectral()) return SampledSpectrum(rgb_);
        return sample(poly_[std::size_t(w.color_space->index())], w);
    }

private:
    Color3 rgb_;
    std::array<UpliftedRgb, RGBColorSpace::kCount> poly_{};
};

} // namespace illum
