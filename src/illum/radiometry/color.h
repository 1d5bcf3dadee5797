// Color3: a dimensionless RGB triple (reflectance, albedo, throughput, filter weights).
#pragma once

#include <algorithm>
#include <cmath>

namespace illum {

struct Color3 {
    float r = 0, g = 0, b = 0;

    constexpr Color3() = default;
    constexpr explicit Color3(float v) : r(v), g(v), b(v) {}
    constexpr Color3(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

    constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }

    constexpr Color3 operator+(Color3 o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Color3 operator-(Color3 o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Color3 operator*(Color3 o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Color3 operator/(Color3 o) const { return {r / o.r, g / o.g, b / o.b}; }
    constexpr Color3 operator*(float s) const { return {r * s, g * s, b * s}; }
    constexpr Color3 operator/(float s) const { return {r / s, g / s, b / s}; }
    constexpr Color3 operator-() const { return {-r, -g, -b}; }
    Color3& operator+=(Color3 o) { return *this = *this + o; }
    Color3& operator-=(Color3 o) { return *this = *this - o; }
    Color3& operator*=(Color3 o) { return *this = *this * o; }
    Color3& operator*=(float s) { return *this = *this * s; }
    Color3& operator/=(float s) { return *this = *this / s; }
    constexpr bool operator==(const Color3&) const = default;

    constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
    constexpr float max_component() const { return std::max(r, std::max(g, b)); }
    constexpr float average() const { return (r + g + b) / 3; }
    // Relative luminance Y of linear sRGB / Rec. 709 primaries (ITU-R BT.709).
    constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
    bool has_negative() const { return r < 0 || g < 0 || b < 0; }
};

constexpr Color3 operator*(float s, Color3 c) { return c * s; }
inline Color3 exp(Color3 c) { return {std::exp(c.r), std::exp(c.g), std::exp(c.b)}; }
inline Color3 sqrt(Color3 c) { return {std::sqrt(c.r), std::sqrt(c.g), std::sqrt(c.b)}; }
inline Color3 clamp(Color3 c, float lo, float hi) {
    return {std::clamp(c.r, lo, hi), std::clamp(c.g, lo, hi), std::clamp(c.b, lo, hi)};
}
inline Color3 lerp(float t, Color3 a, Color3 b) { return a * (1 - t) + b * t; }

} // namespace illum
