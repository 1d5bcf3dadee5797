// The textures of pbrt-v4 scene files, as float and colour textures: image (filtered through a MIP map,
// mipmap.h), checkerboard (2D and 3D, antialiased as pbrt-v4 does), scale, mix, directionmix, bilerp, over
// the mappings of mapping.h. Each evaluates without allocating.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "illum/image/image.h"
#include "illum/texture/mapping.h"
#include "illum/texture/mipmap.h"
#include "illum/texture/texture.h"

namespace illum {

// An image looked up at (s, t) with bilinear filtering at full resolution (the normal map's lookup);
// t = 0 is the image's bottom row, as pbrt-v4 flips t for image textures. Values are scaled and optionally
// inverted (1 - v).
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
        if (!wrap_texel(wrap_, image_->width(), image_->height(), &x, &y)) return Color3(0.0f);
        return (*image_)(x, y);
    }
    std::shared_ptr<const Image> image_;
    WrapMode wrap_;
    float scale_;
    bool invert_;
};

// pbrt-v4's image texture: the MIP map filtered over the footprint at (s, 1 - t), scaled, optionally
// inverted (1 - v, clamped to [0, 1]). pbrt-v4 (5f7a606) flips t but passes ∂t/∂x, ∂t/∂y unchanged, which
// mirrors an EWA ellipse whose axes are sheared; illum negates them with t.
class FilteredImage {
public:
    FilteredImage(MipMap mip, float scale, bool invert)
        : mip_(std::move(mip)), scale_(scale), invert_(invert) {}
    Color3 lookup(const TexCoord2D& c) const {
        Color3 v = mip_.filter({c.st.x, 1 - c.st.y}, {c.dsdx, -c.dtdx}, {c.dsdy, -c.dtdy}) * scale_;
        if (invert_) v = clamp(Color3(1.0f) - v, 0.0f, 1.0f);
        return v;
    }
    const MipMap& mipmap() const { return mip_; }

private:
    MipMap mip_;
    float scale_;
    bool invert_;
};

class ImageColorTexture final : public ColorTexture {
public:
    ImageColorTexture(FilteredImage image, TextureMapping2D m) : image_(std::move(image)), m_(m) {}
    Color3 evaluate(const TextureEvalContext& hit) const override {
        return image_.lookup(m_.map_footprint(hit));
    }

private:
    FilteredImage image_;
    TextureMapping2D m_;
};

// A float image texture: the channels' mean of the filtered colour (pbrt-v4 averages an RGB image's
// channels).
class ImageFloatTexture final : public FloatTexture {
public:
    ImageFloatTexture(FilteredImage image, TextureMapping2D m) : image_(std::move(image)), m_(m) {}
    float evaluate(const TextureEvalContext& hit) const override {
        return image_.lookup(m_.map_footprint(hit)).average();
    }

private:
    FilteredImage image_;
    TextureMapping2D m_;
};

// pbrt-v4's checkerboard antialiasing (PBR 4th ed. §10.5.2 and pbrt-v4's Checkerboard()): the weight of
// tex2 is 1/2 - bf(s, ds) bf(t, dt) / 2 (3D: 1/2 - bf(x) bf(y) bf(z) / 2), where bf(x, r) is the ±1 square
// wave of period 2 filtered by a tent of radius r, bf = (d(x + r) - 2 d(x) + d(x - r)) / r² with
// d(x) = x/2 + y (1 - 2|y|), y = x/2 - ⌊x/2⌋ - 1/2 (its second antiderivative), or the wave itself where
// [x - r, x + r] lies in one cell; r is 1.5 times the largest derivative of that coordinate in x and y.
// The second difference is taken in double (in float it cancels catastrophically for small r), and
// clamped to the wave's range.
inline float checker_wave_filtered(float x, float r) {
    if (std::floor(x - r) == std::floor(x + r)) return (floor_to_int(x) & 1) ? -1.0f : 1.0f;
    auto d = [](double v) {
        double y = v / 2 - std::floor(v / 2) - 0.5;
        return v / 2 + y * (1 - 2 * std::abs(y));
    };
    double xd = x, rd = r;
    double v = (d(xd + rd) - 2 * d(xd) + d(xd - rd)) / (rd * rd);
    return float(std::clamp(v, -1.0, 1.0));
}

// Blends tex1 and tex2 by the weight w of tex2, evaluating each only where its weight is not 0.
template <class Base, class Value>
Value checker_blend(const Base* a, const Base* b, float w, const TextureEvalContext& hit) {
    Value r = Value(0.0f);
    if (w != 1) r = r + a->evaluate(hit) * (1 - w);
    if (w != 0) r = r + b->evaluate(hit) * w;
    return r;
}

// pbrt-v4's 2D checkerboard: tex1 where floor(s) + floor(t) is even, tex2 elsewhere, antialiased.
template <class Base, class Value>
class Checkerboard2D final : public Base {
public:
    Checkerboard2D(const Base* a, const Base* b, TextureMapping2D m) : a_(a), b_(b), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        TexCoord2D c = m_.map_footprint(hit);
        float ds = 1.5f * std::max(std::abs(c.dsdx), std::abs(c.dsdy));
        float dt = 1.5f * std::max(std::abs(c.dtdx), std::abs(c.dtdy));
        float w = 0.5f - checker_wave_filtered(c.st.x, ds) * checker_wave_filtered(c.st.y, dt) / 2;
        return checker_blend<Base, Value>(a_, b_, w, hit);
    }

private:
    const Base *a_, *b_;
    TextureMapping2D m_;
};

// pbrt-v4's 3D checkerboard: tex1 where floor(x) + floor(y) + floor(z) of the point in texture space is
// even, antialiased.
template <class Base, class Value>
class Checkerboard3D final : public Base {
public:
    Checkerboard3D(const Base* a, const Base* b, TextureMapping3D m) : a_(a), b_(b), m_(m) {}
    Value evaluate(const TextureEvalContext& hit) const override {
        Point3f p = m_.map(hit);
        Vector3f dx = m_.dpdx(hit), dy = m_.dpdy(hit);
        float w = 0.5f;
        float prod = 1;
        for (int i = 0; i < 3; ++i)
            prod *= checker_wave_filtered(p[i], 1.5f * std::max(std::abs(dx[i]), std::abs(dy[i])));
        w -= prod / 2;
        return checker_blend<Base, Value>(a_, b_, w, hit);
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
