// The textures of pbrt-v4 scene files, as float and colour textures: uv mapping, image (bilinear),
// checkerboard, scale, mix. Each evaluates without allocating.
#pragma once

#include <cmath>
#include <memory>

#include "illum/image/image.h"
#include "illum/texture/texture.h"

namespace illum {

// pbrt-v4's "uv" mapping: (s, t) = (uscale u + udelta, vscale v + vdelta).
struct UVMapping {
    float su = 1, sv = 1, du = 0, dv = 0;
    Point2f map(const TextureEvalContext& hit) const { return {su * hit.uv.x + du, sv * hit.uv.y + dv}; }
};

enum class WrapMode { Repeat, Clamp, Black };

// An image looked up at (s, t) with bilinear filtering; t = 0 is the image's bottom row, as pbrt-v4
// flips t for image textures. Values are scaled and optionally inverted (1 - v).
class ImageTextureData {
public:
    ImageTextureData(std::shared_ptr<const Image> image, WrapMode wrap, float scale, bool invert)
        : image_(std::move(image)), wrap_(wrap), scale_(scale), invert_(invert) {}
    Color3 lookup(Point2f st) const {
        int w = image_->width(), h = image_->height();
        float x = st.x * w - 0.5f, y = (1 - st.y) * h - 0.5f;
        float fx = std::floor(x), fy = std::floor(y);
        int x0 = floor_to_int(x), y0 = floor_to_int(y);
        float ax = x - fx, ay = y - fy;
        Color3 c = texel(x0, y0) * ((1 - ax) * (1 - ay)) + texel(x0 + 1, y0) * (ax * (1 - ay)) +
                   texel(x0, y0 + 1) * ((1 - ax) * ay) + texel(x0 + 1, y0 + 1) * (ax * ay);
        c *= scale_;
        if (invert_) c = clamp(Color3(1.0f) - c, 0.0f, 1.0f);
        return c;
    }

private:
    Color3 texel(int x, int y) const {
        int w = image_->width(), h = image_->height();
        switch (wrap_) {
        case WrapMode::Repeat:
            x = ((x % w) + w) % w;
            y = ((y % h) + h) % h;
            break;
        case WrapMode::Clamp:
            x = std::clamp(x, 0, w - 1);
            y = std::clamp(y, 0, h - 1);
            break;
        case WrapMode::Black:
            if (x < 0 || y < 0 || x >= w || y >= h) return Color3(0.0f);
            break;
        }
        return (*image_)(x, y);
    }
    std::shared_ptr<const Image> image_;
    WrapMode wrap_;
    float scale_;
    bool invert_;
};

class ImageColorTexture final : public ColorTexture {
public:
    ImageColorTexture(ImageTextureData data, UVMapping m) : data_(std::move(data)), m_(m) {}
    Color3 evaluate(const TextureEvalContext& hit) const override { return data_.lookup(m_.map(hit)); }

private:
    ImageTextureData data_;
    UVMapping m_;
};

class ImageFloatTexture final : public FloatTexture {
public:
    ImageFloatTexture(ImageTextureData data, UVMapping m) : data_(std::move(data)), m_(m) {}
    float evaluate(const TextureEvalContext& hit) const override {
        return data_.lookup(m_.map(hit)).average();
    }

private:
    ImageTextureData data_;
    UVMapping m_;
};

// pbrt-v4's 2D checkerboard: tex1 where floor(s) + floor(t) is even, tex2 elsewhere (no antialiasing).
template <class Base, class Value>
class Checkerboard2D final : public Base {
public:
    Checkerboard2D(const Base* a, const Base* b, UVMapping m) : a_(a), b_(b), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        Point2f st = m_.map(hit);
        int parity = floor_to_int(st.x) ^ floor_to_int(st.y); // the sum's parity is the xor's
        return (parity & 1) == 0 ? a_->evaluate(hit) : b_->evaluate(hit);
    }

private:
    const Base *a_, *b_;
    UVMapping m_;
};

// pbrt-v4 "scale": tex * scale (scale is a float texture).
template <class Base, class Value>
class ScaleTex final : public Base {
public:
    ScaleTex(const Base* t, const FloatTexture* s) : t_(t), s_(s) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        float s = s_->evaluate(hit);
        return s == 0 ? Value(0.0f) : t_->evaluate(hit) * s;
    }

private:
    const Base* t_;
    const FloatTexture* s_;
};

// pbrt-v4 "mix": (1 - amount) tex1 + amount tex2.
template <class Base, class Value>
class MixTex final : public Base {
public:
    MixTex(const Base* a, const Base* b, const FloatTexture* amount) : a_(a), b_(b), amount_(amount) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        float t = amount_->evaluate(hit);
        Value r = Value(0.0f);
        if (t != 1) r = r + a_->evaluate(hit) * (1 - t);
        if (t != 0) r = r + b_->evaluate(hit) * t;
        return r;
    }

private:
    const Base *a_, *b_;
    const FloatTexture* amount_;
};

} // namespace illum
