// Textures give a material parameter at a surface point. Constant and checkerboard here; image textures
// come with the image module. Textures sit below geometry (the accelerator evaluates alpha cut-outs), so
// they see a point through TextureEvalContext, which a SurfaceHit is (as pbrt-v4's TextureEvalContext is
// made from a SurfaceInteraction).
#pragma once

#include <cmath>

#include "illum/math/vector.h"
#include "illum/radiometry/color.h"
#include "illum/radiometry/uplift.h"

namespace illum {

// floor(v) as an int for a texture lookup. A coordinate beyond ±2^30, infinite or NaN (an extreme uv scale,
// a degenerate hit) gives 0 instead of the undefined behaviour of converting it (floats that large are even
// integers anyway, so a checkerboard's parity is unchanged).
inline int floor_to_int(float v) {
    float f = std::floor(v);
    return std::abs(f) < 1073741824.0f ? int(f) : 0;
}

// What a texture may depend on at a surface point, and the point's footprint (pbrt-v4's
// TextureEvalContext): how p and uv change from one pixel sample to the next in x and y (∂p/∂x, ∂p/∂y,
// ∂u/∂x, ...), from ray differentials or the camera's approximation (render/texture_footprint.h). They are
// computed only at hits whose material has a texture that filters (Material::needs_texture_differentials)
// and are zero elsewhere: a zero footprint gives the finest image level, point sampling.
struct TextureEvalContext {
    Point3f p;
    Normal3f n; // geometric normal, on the side the shape's orientation says is outside
    Point2f uv;
    Vector3f dpdx, dpdy;
    float dudx = 0, dudy = 0, dvdx = 0, dvdy = 0;
    // The face a Ptex texture reads (pbrt-v4's faceIndex): the mesh's "faceIndices" entry for the hit's
    // triangle or bilinear patch (a PLY file's "face_indices"), 0 where the shape gives none.
    int face_index = 0;
};

class ColorTexture {
public:
    virtual ~ColorTexture() = default;
    virtual Color3 evaluate(const TextureEvalContext& hit) const = 0;
    // The value as a reflectance at the path's wavelengths (uplift.h): what a material's reflectance reads.
    virtual SampledSpectrum albedo(const TextureEvalContext& hit, const SampledWavelengths& w) const {
        return uplift_albedo(evaluate(hit), w);
    }
    // The value as an unbounded quantity (an index of refraction, an absorption coefficient) at the path's
    // wavelengths: what pbrt-v4's RGBUnboundedSpectrum gives.
    virtual SampledSpectrum unbounded(const TextureEvalContext& hit, const SampledWavelengths& w) const {
        return uplift_unbounded(evaluate(hit), w);
    }
};

class FloatTexture {
public:
    virtual ~FloatTexture() = default;
    virtual float evaluate(const TextureEvalContext& hit) const = 0;
};

class ConstantColorTexture final : public ColorTexture {
public:
    // Both uplifts computed once (as pbrt-v4's constant spectrum textures hold their spectra), not per hit.
    explicit ConstantColorTexture(Color3 c)
        : value_(c), albedo_(c, UpliftKind::Albedo), unbounded_(c, UpliftKind::Unbounded) {}
    Color3 evaluate(const TextureEvalContext&) const override { return value_; }
    SampledSpectrum albedo(const TextureEvalContext&, const SampledWavelengths& w) const override {
        return albedo_.at(w);
    }
    SampledSpectrum unbounded(const TextureEvalContext&, const SampledWavelengths& w) const override {
        return unbounded_.at(w);
    }
    Color3 value() const { return value_; }

private:
    Color3 value_;
    UpliftCache albedo_, unbounded_;
};

class ConstantFloatTexture final : public FloatTexture {
public:
    explicit ConstantFloatTexture(float v) : value_(v) {}
    float evaluate(const TextureEvalContext&) const override { return value_; }

private:
    float value_;
};

// A 2D checkerboard in uv scaled by (su, sv): tex1 where floor(su u) + floor(sv v) is even.
class CheckerboardColorTexture final : public ColorTexture {
public:
    CheckerboardColorTexture(const ColorTexture* a, const ColorTexture* b, float su, float sv)
        : a_(a), b_(b), su_(su), sv_(sv) {}
    Color3 evaluate(const TextureEvalContext& hit) const override {
        // The parity of floor(su u) + floor(sv v), as the xor of the two parities (no overflow).
        int parity = (floor_to_int(hit.uv.x * su_) ^ floor_to_int(hit.uv.y * sv_)) & 1;
        return parity == 0 ? a_->evaluate(hit) : b_->evaluate(hit);
    }

private:
    const ColorTexture *a_, *b_;
    float su_, sv_;
};

} // namespace illum
