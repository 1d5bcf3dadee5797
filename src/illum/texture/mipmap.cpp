#include "illum/texture/mipmap.h"

#include <algorithm>
#include <cmath>

#include "illum/texture/texture.h"

namespace illum {

namespace {

// The box of width r = n_in / n_out over the input, for output index i: the input texels [j0, j1] it
// touches and their overlaps with [i r, (i + 1) r), divided by r (so they sum to 1). At most 3 texels when
// r ≤ 3, which holds for every halving (r = 2 + 1/⌊n/2⌋ ≤ 3); r can be n itself (n ≤ 3) when the output
// has one texel, and then the weights are 1/n over all of it.
struct BoxTaps {
    int j0 = 0, count = 0;
    std::array<float, 4> w{};
};

BoxTaps box_taps(int i, int n_in, int n_out) {
    BoxTaps b;
    double r = double(n_in) / n_out;
    double a = i * r, e = (i + 1) * r;
    b.j0 = int(std::floor(a));
    int j1 = std::min(n_in - 1, int(std::ceil(e)) - 1);
    b.count = j1 - b.j0 + 1;
    for (int k = 0; k < b.count; ++k) {
        double lo = std::max(a, double(b.j0 + k)), hi = std::min(e, double(b.j0 + k + 1));
        b.w[std::size_t(k)] = float(std::max(0.0, hi - lo) / r);
    }
    return b;
}

// e^{-2Q} - e^{-2} at Q = i / (n - 1), i = 0..n-1 (the last entry is 0).
constexpr int kEwaTableSize = 128;
const std::array<float, kEwaTableSize>& ewa_table() {
    static const std::array<float, kEwaTableSize> table = [] {
        std::array<float, kEwaTableSize> t{};
        for (int i = 0; i < kEwaTableSize; ++i) {
            double q = double(i) / (kEwaTableSize - 1);
            t[std::size_t(i)] = float(std::exp(-2 * q) - std::exp(-2.0));
        }
        return t;
    }();
    return table;
}

float length2(Vector2f v) { return v.x * v.x + v.y * v.y; }

} // namespace

Image downsample_box(const Image& in) {
    const int w = in.width(), h = in.height();
    const int w2 = std::max(1, w / 2), h2 = std::max(1, h / 2);
    // Separable: rows first (w -> w2), then columns (h -> h2).
    Image rows(w2, h);
    for (int x = 0; x < w2; ++x) {
        BoxTaps b = box_taps(x, w, w2);
        for (int y = 0; y < h; ++y) {
            Color3 c(0.0f);
            for (int k = 0; k < b.count; ++k) c += in(b.j0 + k, y) * b.w[std::size_t(k)];
            rows(x, y) = c;
        }
    }
    Image out(w2, h2);
    for (int y = 0; y < h2; ++y) {
        BoxTaps b = box_taps(y, h, h2);
        for (int x = 0; x < w2; ++x) {
            Color3 c(0.0f);
            for (int k = 0; k < b.count; ++k) c += rows(x, b.j0 + k) * b.w[std::size_t(k)];
            out(x, y) = c;
        }
    }
    return out;
}

MipPyramid::MipPyramid(std::shared_ptr<const Image> image) : image_(std::move(image)) {
    finest_ = std::max(image_->width(), image_->height());
    const Image* prev = image_.get();
    // Count first, so that the vector never reallocates (prev points into it).
    int n = 0;
    for (int w = image_->width(), h = image_->height(); w > 1 || h > 1;
         w = std::max(1, w / 2), h = std::max(1, h / 2))
        ++n;
    extra_.reserve(std::size_t(n));
    for (int k = 0; k < n; ++k) {
        extra_.push_back(downsample_box(*prev));
        prev = &extra_.back();
    }
}

std::size_t MipPyramid::extra_texels() const {
    std::size_t n = 0;
    for (const Image& im : extra_) n += im.pixel_count();
    return n;
}

Color3 MipMap::texel(int level, int x, int y) const {
    const Image& im = pyramid_->level(level);
    if (!wrap_texel(wrap_, im.width(), im.height(), &x, &y)) return Color3(0.0f);
    return im(x, y);
}

Color3 MipMap::bilerp(int level, Point2f st) const {
    const Image& im = pyramid_->level(level);
    float x = st.x * im.width() - 0.5f, y = st.y * im.height() - 0.5f;
    float fx = std::floor(x), fy = std::floor(y);
    int x0 = floor_to_int(x), y0 = floor_to_int(y);
    float ax = x - fx, ay = y - fy;
    return texel(level, x0, y0) * ((1 - ax) * (1 - ay)) + texel(level, x0 + 1, y0) * (ax * (1 - ay)) +
           texel(level, x0, y0 + 1) * ((1 - ax) * ay) + texel(level, x0 + 1, y0 + 1) * (ax * ay);
}

float MipMap::ewa_weight(float q) {
    int i = std::min(int(q * kEwaTableSize), kEwaTableSize - 1);
    return ewa_table()[std::size_t(std::max(i, 0))];
}

Color3 MipMap::ewa(int level, Point2f st, Vector2f dst0, Vector2f dst1) const {
    const int n = pyramid_->levels();
    if (level >= n) return texel(n - 1, 0, 0);
    const Image& im = pyramid_->level(level);
    const float w = float(im.width()), h = float(im.height());
    // To this level's texels, centres at integers.
    float s = st.x * w - 0.5f, t = st.y * h - 0.5f;
    if (!(std::abs(s) < 1e6f && std::abs(t) < 1e6f)) return bilerp(level, st); // NaN or meaningless
    float a0s = dst0.x * w, a0t = dst0.y * h, a1s = dst1.x * w, a1t = dst1.y * h;
    float A = a0t * a0t + a1t * a1t + 1;
    float B = -2 * (a0s * a0t + a1s * a1t);
    float C = a0s * a0s + a1s * a1s + 1;
    float inv_f = 1 / (A * C - B * B * 0.25f);
    A *= inv_f, B *= inv_f, C *= inv_f;
    // The ellipse's bounding box: |Δs| ≤ sqrt(4C / det), |Δt| ≤ sqrt(4A / det), det = 4AC - B².
    float det = 4 * A * C - B * B;
    float ds = std::sqrt(std::max(0.0f, 4 * C / det)), dt = std::sqrt(std::max(0.0f, 4 * A / det));
    // Keep the loop bounded even for a degenerate ellipse (maxanisotropy bounds it in normal use).
    // det = 4 / (AC - B²/4 before the division) > 0; bound the loop should it overflow anyway.
    if (!(ds < 1e6f)) ds = 1e6f;
    if (!(dt < 1e6f)) dt = 1e6f;
    int s0 = int(std::ceil(s - ds)), s1 = int(std::floor(s + ds));
    int t0 = int(std::ceil(t - dt)), t1 = int(std::floor(t + dt));
    Color3 sum(0.0f);
    float sum_w = 0;
    for (int it = t0; it <= t1; ++it) {
        float tt = float(it) - t;
        for (int is = s0; is <= s1; ++is) {
            float ss = float(is) - s;
            float q = A * ss * ss + B * ss * tt + C * tt * tt;
            if (q < 1) {
                float wgt = ewa_weight(q);
                sum += texel(level, is, it) * wgt;
                sum_w += wgt;
            }
        }
    }
    // The widened ellipse always holds the nearest texel centre, whose weight is > 0 unless Q rounds to the
    // last table entry; fall back to bilinear then.
    return sum_w > 0 ? sum / sum_w : bilerp(level, st);
}

Color3 MipMap::filter(Point2f st, Vector2f dst0, Vector2f dst1) const {
    const int n = pyramid_->levels();
    const float res = float(pyramid_->finest_resolution());
    if (filter_ != MipFilter::EWA) {
        float width = 2 * std::max({std::abs(dst0.x), std::abs(dst0.y), std::abs(dst1.x), std::abs(dst1.y)});
        float level = std::log2(std::max(width * res, 1e-8f));
        if (level >= float(n - 1)) return texel(n - 1, 0, 0);
        int il = std::max(0, int(std::floor(level)));
        switch (filter_) {
        case MipFilter::Point: {
            const Image& im = pyramid_->level(il);
            return texel(il, int(std::round(st.x * im.width() - 0.5f)),
                         int(std::round(st.y * im.height() - 0.5f)));
        }
        case MipFilter::Bilinear:
            return bilerp(il, st);
        default: {
            if (level <= 0) return bilerp(0, st);
            float f = level - float(il);
            return bilerp(il, st) * (1 - f) + bilerp(il + 1, st) * f;
        }
        }
    }
    if (length2(dst0) < length2(dst1)) std::swap(dst0, dst1);
    float longer = std::sqrt(length2(dst0)), shorter = std::sqrt(length2(dst1));
    if (shorter * max_anisotropy_ < longer && shorter > 0) {
        float scale = longer / (shorter * max_anisotropy_);
        dst1 = dst1 * scale;
        shorter *= scale;
    }
    if (!(shorter > 0) || !std::isfinite(longer)) return bilerp(0, st);
    float lod = std::max(0.0f, std::log2(shorter * res));
    int il = int(std::floor(lod));
    float f = lod - float(il);
    Color3 c = ewa(il, st, dst0, dst1);
    if (f > 0) c = c * (1 - f) + ewa(il + 1, st, dst0, dst1) * f;
    return c;
}

} // namespace illum
