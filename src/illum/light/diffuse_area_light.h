// A diffuse (Lambertian) area emitter on any AreaShape, one- or two-sided: of uniform radiance L, or
// (pbrt-v4's "filename") of radiance from an image looked up by the surface's uv,
//   L(p) = s · RGB_illuminant(bilinear(image, (u, 1 - v))),
// as pbrt-v4's DiffuseAreaLight::L does (v flipped: the image's top row at v = 1, bilinear with clamping).
// The power is π ∫_A L dA (twice that two-sided). With an image, the integral over the part of the image the
// shape's uv covers is computed once by quadrature over the shape's own area sampling (image_integral);
// pbrt-v4 instead takes the whole image's mean for every light ("assume no distortion"), which is right only
// for a single shape whose uv spans the image evenly, and not for the triangles of a mesh.
#pragma once

#include <memory>

#include "illum/image/image.h"

#include "illum/geometry/shape.h"
#include "illum/light/light.h"
#include "illum/radiometry/emission.h"
#include "illum/texture/texture.h"

namespace illum {

class DiffuseAreaLight final : public Light {
public:
    DiffuseAreaLight(const AreaShape* shape, Emission radiance, bool two_sided)
        : Light(LightType::Area), shape_(shape), radiance_(std::move(radiance)), two_sided_(two_sided) {}
    // An image emitter: `scale` s multiplies the image's RGB (non-negative, linear).
    DiffuseAreaLight(const AreaShape* shape, std::shared_ptr<const Image> image, float scale, bool two_sided);

    // The shape's "alpha" cut-out (nullptr: opaque). As pbrt-v4 does, a point the cut-out removes does not
    // emit: alpha 0 never, alpha 1 always, alpha a in between with probability a by a hash of the point.
    void set_alpha(const FloatTexture* alpha) { alpha_ = alpha; }
    bool masked(Point3f p, Normal3f n, Point2f uv) const;

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const override;
    Radiance3 radiance(const SurfaceHit& hit, Vector3f w, const SampledWavelengths& lambda) const override {
        if (alpha_ && masked(hit.p, hit.n, hit.uv)) return {};
        return emitted(hit.n, hit.uv, w, lambda);
    }
    // Φ = π A L for a one-sided Lambertian emitter, twice that for a two-sided one.
    Power3 power() const override;
    // The shape's box and cone of normals, emitting over the hemisphere (θe = π/2); phi = 2π L A, twice
    // the power of one side (light_bounds.h).
    std::optional<LightBounds> bounds() const override;
    AreaPdf pdf_le_position(const SurfaceHit& hit) const override { return shape_->area_pdf(hit.p); }
    // A point uniform by area, a cosine-weighted direction about its normal (either side with
    // probability 1/2 when two-sided): flux = L cos θ / (p_A · cos θ / π) = π L / p_A (× 2 two-sided).
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    // The shape's area density at the ray's origin (1 / A for uniform samplers) and the cosine-weighted
    // density about n (halved and on either side when two-sided).
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    // The radiance leaving the point of normal n and surface coordinates uv towards w.
    Radiance3 emitted(Normal3f n, Point2f uv, Vector3f w, const SampledWavelengths& lambda) const;
    Radiance3 emitted(Normal3f n, Vector3f w, const SampledWavelengths& lambda) const {
        return emitted(n, Point2f{0, 0}, w, lambda);
    }
    const AreaShape* shape() const { return shape_; }
    bool two_sided() const { return two_sided_; }

private:
    const AreaShape* shape_;
    Emission radiance_;
    bool two_sided_;
    const FloatTexture* alpha_ = nullptr;
    std::shared_ptr<const Image> image_; // with an image: radiance_ is the grey scale s
    float image_scale_ = 0;
    Color3 image_integral_; // ∫_A RGB(uv(p)) dA, before the scale
};

// ∫_A image(u, 1 - v) dA over the shape (RGB, bilinear lookups), by the shape's area sampling at the centres
// of an n x n grid of strata, each point weighed by 1 / p_A; n grows with the number of texels the shape's
// uv covers (about 4 points per texel side, 8 ≤ n ≤ 256).
Color3 image_integral(const AreaShape& shape, const Image& image);

} // namespace illum
