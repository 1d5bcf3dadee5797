#include "illum/image/tonemap.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace illum {

std::optional<ToneMap> tonemap_from_string(std::string_view name) {
    std::string s(name);
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (s == "clamp") return ToneMap::Clamp;
    if (s == "reinhard") return ToneMap::Reinhard;
    if (s == "aces") return ToneMap::Aces;
    return std::nullopt;
}

const char* to_string(ToneMap t) {
    switch (t) {
    case ToneMap::Clamp:
        return "clamp";
    case ToneMap::Reinhard:
        return "reinhard";
    case ToneMap::Aces:
        return "aces";
    }
    return "?";
}

namespace {

// Narkowicz, "ACES Filmic Tone Mapping Curve" (2016 blog post,
// https://knarkowicz.wordpress.com/2016/01/06/aces-filmic-tone-mapping-curve/): a rational fit of the ACES
// reference rendering + output transforms, f(x) = x (a x + b) / (x (c x + d) + e), saturated to [0, 1].
// It is applied to x as given (no hidden pre-exposure); use exposure_stops to adjust.
// f' > 0 for x >= 0 since its numerator (ad - bc) x^2 + 2ae x + be has positive coefficients.
float aces_narkowicz(float x) {
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp(x * (a * x + b) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

} // namespace

float tonemap(float x, ToneMap t) {
    if (std::isnan(x) || x <= 0) return 0.0f;
    if (std::isinf(x)) return 1.0f;
    switch (t) {
    case ToneMap::Clamp:
        return std::min(x, 1.0f);
    // The simple global operator of Reinhard et al. 2002, "Photographic Tone Reproduction for Digital
    // Images", eq. 3, L_d = L / (1 + L), applied to each RGB channel separately (not to luminance), so the
    // result stays in [0, 1) without a gamut-clipping step; saturated colours drift towards white.
    case ToneMap::Reinhard:
        return x / (1.0f + x);
    case ToneMap::Aces:
        return aces_narkowicz(x);
    }
    return 0.0f;
}

Color3 tonemap(Color3 c, ToneMap t, float exposure_stops) {
    const float scale = std::exp2(exposure_stops);
    return {tonemap(c.r * scale, t), tonemap(c.g * scale, t), tonemap(c.b * scale, t)};
}

Image tonemapped(const Image& image, ToneMap t, float exposure_stops) {
    Image out(image.width(), image.height());
    const Color3* in = image.data();
    Color3* o = out.data();
    for (std::size_t i = 0; i < image.pixel_count(); ++i) o[i] = tonemap(in[i], t, exposure_stops);
    return out;
}

float srgb_encode(float x) {
    if (!(x > 0)) return 0.0f; // also NaN
    if (x >= 1) return 1.0f;
    if (x <= 0.0031308f) return 12.92f * x;
    return 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float v) {
    if (!(v > 0)) return 0.0f;
    if (v >= 1) return 1.0f;
    if (v <= 0.04045f) return v / 12.92f;
    return std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float srgb8_decode(unsigned char code) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_decode(float(i) / 255.0f);
        return t;
    }();
    return table[code];
}

unsigned char srgb8_encode(float linear) {
    return static_cast<unsigned char>(std::lround(255.0f * srgb_encode(linear)));
}

} // namespace illum
