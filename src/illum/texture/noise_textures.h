// pbrt-v4's noise textures (PBR 4th ed. §10.6) over the 3D mapping (the point in texture space), or the 2D
// one for dots: "fbm" and "wrinkled" (fractional Brownian motion and turbulence; octaves, roughness = ω),
// "windy" (|fbm(0.1 p, ω 0.5, 3 octaves)| · fbm(p, 0.5, 6)), "marble" (a colour spline at
// 0.5 + 0.5 sin(p_y + variation · fbm(p)), p scaled by `scale`) and "dots" (polka dots of radius 0.35
// jittered by noise in every cell whose noise is positive). The sums drop the octaves finer than the hit's
// footprint in texture space (noise.h), as pbrt-v4 does.
#pragma once

#include <algorithm>
#include <cmath>

#include "illum/texture/mapping.h"
#include "illum/texture/noise.h"
#include "illum/texture/texture.h"

namespace illum {

class FbmTexture final : public FloatTexture {
public:
    FbmTexture(TextureMapping3D m, int octaves, float omega) : m_(m), octaves_(octaves), omega_(omega) {}
    float evaluate(const TextureEvalContext& hit) const override {
        return fbm(m_.map(hit), m_.dpdx(hit), m_.dpdy(hit), omega_, octaves_);
    }

private:
    TextureMapping3D m_;
    int octaves_;
    float omega_;
};

class WrinkledTexture final : public FloatTexture {
public:
    WrinkledTexture(TextureMapping3D m, int octaves, float omega) : m_(m), octaves_(octaves), omega_(omega) {}
    float evaluate(const TextureEvalContext& hit) const override {
        return turbulence(m_.map(hit), m_.dpdx(hit), m_.dpdy(hit), omega_, octaves_);
    }

private:
    TextureMapping3D m_;
    int octaves_;
    float omega_;
};

class WindyTexture final : public FloatTexture {
public:
    explicit WindyTexture(TextureMapping3D m) : m_(m) {}
    float evaluate(const TextureEvalContext& hit) const override {
        Point3f p = m_.map(hit);
        Vector3f dpdx = m_.dpdx(hit), dpdy = m_.dpdy(hit);
        float wind_strength = fbm(scaled(p, 0.1f), dpdx * 0.1f, dpdy * 0.1f, 0.5f, 3);
        float wave_height = fbm(p, dpdx, dpdy, 0.5f, 6);
        return std::abs(wind_strength) * wave_height;
    }

private:
    TextureMapping3D m_;
};

// The marble's colour: a cubic Bézier spline through pbrt-v4's nine greys and blue-greys (segments of four
// control points, stepping by one), times 1.5, as an albedo.
class MarbleTexture final : public ColorTexture {
public:
    MarbleTexture(TextureMapping3D m, int octaves, float omega, float scale, float variation)
        : m_(m), octaves_(octaves), omega_(omega), scale_(scale), variation_(variation) {}
    Color3 evaluate(const TextureEvalContext& hit) const override {
        Point3f p = scaled(m_.map(hit), scale_);
        float marble =
            p.y + variation_ * fbm(p, m_.dpdx(hit) * scale_, m_.dpdy(hit) * scale_, omega_, octaves_);
        float t = 0.5f + 0.5f * std::sin(marble);
        static constexpr Color3 kColors[] = {{.58f, .58f, .6f}, {.58f, .58f, .6f}, {.58f, .58f, .6f},
                                             {.5f, .5f, .5f},   {.6f, .59f, .58f}, {.58f, .58f, .6f},
                                             {.58f, .58f, .6f}, {.2f, .2f, .33f},  {.58f, .58f, .6f}};
        constexpr int kSegments = int(sizeof(kColors) / sizeof(kColors[0])) - 3;
        int first = std::min(int(std::floor(t * kSegments)), kSegments - 1);
        t = t * kSegments - float(first);
        const Color3* c = kColors + first;
        // de Casteljau.
        Color3 a = lerp(c[0], c[1], t), b = lerp(c[1], c[2], t), d = lerp(c[2], c[3], t);
        Color3 ab = lerp(a, b, t), bd = lerp(b, d, t);
        return lerp(ab, bd, t) * 1.5f;
    }

private:
    static Color3 lerp(Color3 a, Color3 b, float t) { return a * (1 - t) + b * t; }
    TextureMapping3D m_;
    int octaves_;
    float omega_, scale_, variation_;
};

// Whether (s, t) lies in a polka dot (pbrt-v4's InsidePolkaDot).
inline bool inside_polka_dot(Point2f st) {
    const int s_cell = int(std::floor(st.x + 0.5f)), t_cell = int(std::floor(st.y + 0.5f));
    if (!(perlin_noise(float(s_cell) + 0.5f, float(t_cell) + 0.5f) > 0)) return false;
    constexpr float kRadius = 0.35f, kMaxShift = 0.5f - kRadius;
    float s_center = float(s_cell) + kMaxShift * perlin_noise(float(s_cell) + 1.5f, float(t_cell) + 2.8f);
    float t_center = float(t_cell) + kMaxShift * perlin_noise(float(s_cell) + 4.5f, float(t_cell) + 9.8f);
    float ds = st.x - s_center, dt = st.y - t_center;
    return ds * ds + dt * dt < kRadius * kRadius;
}

template <class Base, class Value>
class DotsTex final : public Base {
public:
    DotsTex(const Base* inside, const Base* outside, TextureMapping2D m)
        : inside_(inside), outside_(outside), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        return inside_polka_dot(m_.map(hit)) ? inside_->evaluate(hit) : outside_->evaluate(hit);
    }

private:
    const Base *inside_, *outside_;
    TextureMapping2D m_;
};

} // namespace illum
