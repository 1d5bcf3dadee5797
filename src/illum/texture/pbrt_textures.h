// The textures of pbrt-v4 scene files, as float and colour textures: image (bilinear), checkerboard (2D and
// 3D), scale, mix, directionmix, bilerp, over the mappings of mapping.h. Each evaluates without allocating.
#pragma once

#include <cmath>
#include <memory>

#include "illum/image/image.h"
#include "illum/texture/mapping.h"
#include "illum/texture/texture.h"

namespace illum {

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
    ImageColorTexture(ImageTextureData data, TextureMapping2D m) : data_(std::move(data)), m_(m) {}
    Color3 evaluate(const TextureEvalContext& hit) const override { return data_.lookup(m_.map(hit)); }

private:
    ImageTextureData data_;
    TextureMapping2D m_;
};

class ImageFloatTexture final : public FloatTexture {
public:
    ImageFloatTexture(ImageTextureData data, TextureMapping2D m) : data_(std::move(data)), m_(m) {}
    float evaluate(const TextureEvalContext& hit) const override {
        return data_.lookup(m_.map(hit)).average();
    }

private:
    ImageTextureData data_;
    TextureMapping2D m_;
};

// pbrt-v4's 2D checkerboard: tex1 where floor(s) + floor(t) is even, tex2 elsewhere (no antialiasing).
template <class Base, class Value>
class Checkerboard2D final : public Base {
public:
    Checkerboard2D(const Base* a, const Base* b, TextureMapping2D m) : a_(a), b_(b), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        Point2f st = m_.map(hit);
        int parity = floor_to_int(st.x) ^ floor_to_int(st.y); // the sum's parity is the xor's
        return (parity & 1) == 0 ? a_->evaluate(hit) : b_->evaluate(hit);
    }

private:
    const Base *a_, *b_;
    TextureMapping2D m_;
};

// pbrt-v4's 3D checkerboard: tex1 where floor(x) + floor(y) + floor(z) of the point in texture space is even.
template <class Base, class Value>
class Checkerboard3D final : public Base {
public:
    Checkerboard3D(const Base* a, const Base* b, TextureMapping3D m) : a_(a), b_(b), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        Point3f p = m_.map(hit);
        int parity = floor_to_int(p.x) ^ floor_to_int(p.y) ^ floor_to_int(p.z);
        return (parity & 1) == 0 ? a_->evaluate(hit) : b_->evaluate(hit);
    }

private:
    const Base *a_, *b_;
    TextureMapping3D m_;
};

// pbrt-v4 "bilerp": the bilinear interpolation of four corner values over (s, t),
//   (1-s)(1-t) v00 + s(1-t) v10 + (1-s)t v01 + st v11 (pbrt-v4 does not clamp s, t to [0, 1]).
template <class Base, class Value>
class BilerpTex final : public Base {
public:
    BilerpTex(const Base* v00, const Base* v01, const Base* v10, const Base* v11, TextureMapping2D m)
        : v00_(v00), v01_(v01), v10_(v10), v11_(v11), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        Point2f st = m_.map(hit);
        float s = st.x, t = st.y;
        return v00_->evaluate(hit) * ((1 - s) * (1 - t)) + v10_->evaluate(hit) * (s * (1 - t)) +
               v01_->evaluate(hit) * ((1 - s) * t) + v11_->evaluate(hit) * (s * t);
    }

private:
    const Base *v00_, *v01_, *v10_, *v11_;
    TextureMapping2D m_;
};

// pbrt-v4 "directionmix": a = |n · dir| (the geometric normal, dir normalised in world space);
// a tex1 + (1 - a) tex2, each evaluated only where its weight is not 0.
template <class Base, class Value>
class DirectionMixTex final : public Base {
public:
    DirectionMixTex(const Base* a, const Base* b, Vector3f dir) : a_(a), b_(b), dir_(dir) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        float amount = std::abs(dot(Vector3f(hit.n), dir_));
        Value r = Value(0.0f);
        if (amount != 0) r = r + a_->evaluate(hit) * amount;
        if (amount != 1) r = r + b_->evaluate(hit) * (1 - amount);
        return r;
    }

private:
    const Base *a_, *b_;
    Vector3f dir_;
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
