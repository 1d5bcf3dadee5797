// SampledSpectrum: the values of a spectral quantity at the four wavelengths a path carries (spectral
// mode), or its red, green and blue in lanes 0-2 (RGB mode, lane 3 a copy of green so that every lane
// stays a meaningful number). One type for both modes: the BSDFs, lights and integrators are written once
// on it, and the mode is a property of the path's SampledWavelengths, not of the code (docs/
// architecture.md, "Spectral and RGB modes").
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/radiometry/color.h"

namespace illum {

inline constexpr int kSpectrumSamples = 4;

struct SampledSpectrum {
    float c[kSpectrumSamples] = {0, 0, 0, 0};

    constexpr SampledSpectrum() = default;
    constexpr explicit SampledSpectrum(float v) : c{v, v, v, v} {}
    constexpr SampledSpectrum(float a, float b, float d, float e) : c{a, b, d, e} {}
    // RGB mode's lanes: r, g, b and g again.
    constexpr explicit SampledSpectrum(Color3 rgb) : c{rgb.r, rgb.g, rgb.b, rgb.g} {}

    constexpr float operator[](int i) const { return c[i]; }
    float& operator[](int i) { return c[i]; }
    // RGB mode: the colour in lanes 0-2.
    constexpr Color3 rgb() const { return {c[0], c[1], c[2]}; }

#define ILLUM_LANES(op)                                                                                      \
    constexpr SampledSpectrum operator op(SampledSpectrum o) const {                                         \
        return {c[0] op o.c[0], c[1] op o.c[1], c[2] op o.c[2], c[3] op o.c[3]};                             \
    }                                                                                                        \
    constexpr SampledSpectrum operator op(float s) const {                                                   \
        return {c[0] op s, c[1] op s, c[2] op s, c[3] op s};                                                 \
    }                                                                                                        \
    SampledSpectrum& operator op##=(SampledSpectrum o) { return *this = *this op o; }                        \
    SampledSpectrum& operator op##=(float s) { return *this = *this op s; }
    ILLUM_LANES(+)
    ILLUM_LANES(-)
    ILLUM_LANES(*)
    ILLUM_LANES(/)
#undef ILLUM_LANES
    constexpr SampledSpectrum operator-() const { return {-c[0], -c[1], -c[2], -c[3]}; }
    constexpr bool operator==(const SampledSpectrum&) const = default;

    constexpr bool is_black() const { return c[0] == 0 && c[1] == 0 && c[2] == 0 && c[3] == 0; }
    constexpr float max_component() const { return std::max(std::max(c[0], c[1]), std::max(c[2], c[3])); }
    constexpr float average() const { return (c[0] + c[1] + c[2] + c[3]) / kSpectrumSamples; }
    bool is_finite() const {
        return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]);
    }
    bool has_negative() const { return c[0] < 0 || c[1] < 0 || c[2] < 0 || c[3] < 0; }
};

constexpr SampledSpectrum operator*(float s, SampledSpectrum v) { return v * s; }
constexpr SampledSpectrum operator/(float s, SampledSpectrum v) { return SampledSpectrum(s) / v; }
// A grey argument (every lane equal: a grey medium's σ_t d, the common case in fog) takes one exp, not four.
inline SampledSpectrum exp(SampledSpectrum v) {
    if (v[0] == v[1] && v[1] == v[2] && v[2] == v[3]) return SampledSpectrum(std::exp(v[0]));
    return {std::exp(v[0]), std::exp(v[1]), std::exp(v[2]), std::exp(v[3])};
}
inline SampledSpectrum sqrt(SampledSpectrum v) {
    return {std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
}
inline SampledSpectrum clamp(SampledSpectrum v, float lo, float hi) {
    return {std::clamp(v[0], lo, hi), std::clamp(v[1], lo, hi), std::clamp(v[2], lo, hi),
            std::clamp(v[3], lo, hi)};
}
inline SampledSpectrum lerp(float t, SampledSpectrum a, SampledSpectrum b) { return a * (1 - t) + b * t; }
// a / b with 0 where b is 0 (a terminated wavelength's pdf).
inline SampledSpectrum safe_div(SampledSpectrum a, SampledSpectrum b) {
    SampledSpectrum r;
    for (int i = 0; i < kSpectrumSamples; ++i) r[i] = b[i] != 0 ? a[i] / b[i] : 0;
    return r;
}

} // namespace illum
