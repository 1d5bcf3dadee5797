// Image filtering for image textures as pbrt-v4 does it (PBR 4th ed. §10.4.3; Williams 1983, "Pyramidal
// parametrics"; Heckbert 1989, "Fundamentals of texture mapping and image warping", EWA):
//
// - The pyramid: level 0 is the image itself; level k+1 has max(1, ⌊w_k/2⌋) x max(1, ⌊h_k/2⌋) texels, each
//   the area-weighted box average of the part of level k it covers (2x2 texels for even sizes; for an odd
//   size the box spans 2 + 1/⌊w/2⌋ texels, the outer ones weighted by the fraction inside). pbrt-v4 first
//   resamples an image whose sides are not powers of two up to the next power (a Lanczos filter, up to 4x
//   the texels) and then averages 2x2 blocks; illum keeps the image as it is (level 0 is exact, no ringing)
//   and so the pyramid's extra levels cost at most 1/3 of the image (Σ 4^-k), plus at most 2 max(w, h) /
//   min(w, h) texels once the shorter side has reached one texel. Every level has the image's mean.
// - Levels are chosen as pbrt-v4 does, by the footprint's width in texels of level 0: level
//   ℓ = log2(width · max(w, h)), which is pbrt-v4's nLevels - 1 + log2(width) for a square power of two.
// - Filters, for a lookup at (s, t) with footprint axes (∂s/∂x, ∂t/∂x) and (∂s/∂y, ∂t/∂y):
//   point: the nearest texel of level ⌊ℓ⌋; bilinear: bilinear interpolation in level ⌊ℓ⌋; trilinear:
//   bilinear in levels ⌊ℓ⌋ and ⌊ℓ⌋+1 blended by ℓ - ⌊ℓ⌋; width = 2 max |axis components| (all three return
//   the coarsest level's texel when ℓ reaches it, and use level 0 when ℓ < 0).
//   ewa: the longer axis a0 and shorter a1, a1 lengthened so that |a0| ≤ maxanisotropy |a1|; level
//   ℓ = max(0, log2(|a1| · max(w, h))); at levels ⌊ℓ⌋ and ⌊ℓ⌋+1 (blended) the texels whose centres lie in
//   the ellipse Q(Δs, Δt) = A Δs² + B Δs Δt + C Δt² < 1, with (in that level's texels)
//   A = a0t² + a1t² + 1, B = -2 (a0s a0t + a1s a1t), C = a0s² + a1s² + 1 divided by AC - B²/4 (the ellipse
//   of the two axes widened by one texel, Heckbert's reconstruction term), are averaged with the truncated
//   Gaussian weights e^{-2Q} - e^{-2} (tabulated at 128 values of Q as pbrt-v4 does).
// Wrapping (repeat, clamp, black) applies to every texel read.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "illum/image/image.h"
#include "illum/math/vector.h"

namespace illum {

enum class WrapMode { Repeat, Clamp, Black, OctahedralSphere };

// A texel address outside a w×h image brought inside by the wrap mode; false: the texel is black. The
// octahedral sphere's wrap (pbrt-v4's WrapMode::OctahedralSphere, for equal-area octahedral maps of the
// sphere): past a left or right edge the address mirrors across that edge and across the middle row, past
// the top or bottom edge across that edge and the middle column, so neighbours across the map's border
// are the sphere's neighbours.
inline bool wrap_texel(WrapMode mode, int w, int h, int* px, int* py) {
    int& x = *px;
    int& y = *py;
    switch (mode) {
    case WrapMode::Repeat:
        x %= w;
        if (x < 0) x += w;
        y %= h;
        if (y < 0) y += h;
        return true;
    case WrapMode::Clamp:
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        return true;
    case WrapMode::Black:
        return x >= 0 && y >= 0 && x < w && y < h;
    case WrapMode::OctahedralSphere:
        if (x < 0) {
            x = -x;
            y = h - 1 - y;
        } else if (x >= w) {
            x = 2 * w - 1 - x;
            y = h - 1 - y;
        }
        if (y < 0) {
            x = w - 1 - x;
            y = -y;
        } else if (y >= h) {
            x = w - 1 - x;
            y = 2 * h - 1 - y;
        }
        // (A filter wider than the image can still step past the far side: clamped there.)
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        return true;
    }
    return true;
}
enum class MipFilter { Point, Bilinear, Trilinear, EWA };

// The pyramid of one image: level 0 shares the image, the others are made once (scene build).
class MipPyramid {
public:
    explicit MipPyramid(std::shared_ptr<const Image> image);

    int levels() const { return int(extra_.size()) + 1; }
    const Image& level(int k) const { return k == 0 ? *image_ : extra_[std::size_t(k) - 1]; }
    // The texels of levels 1 and above (what the pyramid adds to the image).
    std::size_t extra_texels() const;
    // max(w, h) of level 0, which converts a footprint in (s, t) to texels.
    int finest_resolution() const { return finest_; }

private:
    std::shared_ptr<const Image> image_;
    std::vector<Image> extra_;
    int finest_;
};

// The box average that makes the next level: max(1, ⌊w/2⌋) x max(1, ⌊h/2⌋) texels.
Image downsample_box(const Image& in);

// A filtered lookup into a pyramid: (s, t) in [0, 1]² span the image with t = 0 at its top row (the image
// texture flips t before asking). Allocates nothing.
class MipMap {
public:
    MipMap(std::shared_ptr<const MipPyramid> pyramid, MipFilter filter, WrapMode wrap, float max_anisotropy)
        : pyramid_(std::move(pyramid)), filter_(filter), wrap_(wrap), max_anisotropy_(max_anisotropy) {}

    Color3 filter(Point2f st, Vector2f dst0, Vector2f dst1) const;

    // The parts, for tests.
    Color3 texel(int level, int x, int y) const;
    Color3 bilerp(int level, Point2f st) const;
    Color3 ewa(int level, Point2f st, Vector2f dst0, Vector2f dst1) const;
    // The EWA weight at Q (the ellipse's quadratic form) in [0, 1): e^{-2Q} - e^{-2}, tabulated.
    static float ewa_weight(float q);

    const MipPyramid& pyramid() const { return *pyramid_; }
    MipFilter filter_kind() const { return filter_; }

private:
    std::shared_ptr<const MipPyramid> pyramid_;
    MipFilter filter_;
    WrapMode wrap_;
    float max_anisotropy_;
};

} // namespace illum
