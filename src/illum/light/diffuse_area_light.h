// A diffuse (Lambertian) area emitter of uniform radiance L on any AreaShape, one- or two-sided.
#pragma once

#include "illum/geometry/shape.h"
#include "illum/light/light.h"
#include "illum/radiometry/emission.h"
#include "illum/texture/texture.h"

namespace illum {

class DiffuseAreaLight final : public Light {
public:
    DiffuseAreaLight(const AreaShape* shape, Emission radiance, bool two_sided)
        : Light(LightType::Area), shape_(shape), radiance_(std::move(radiance)), two_sided_(two_sided) {}

    // The shape's "alpha" cut-out (nullptr: opaque). As pbrt-v4 does, a point the cut-out removes does not
    // emit: alpha 0 never, alpha 1 always, alpha a in between with probability a by a hash of the point.
    void set_alpha(const FloatTexture* alpha) { alpha_ = alpha; }
    bool masked(Point3f p, Normal3f n, Point2f uv) const;

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const override;
    Radiance3 radiance(const SurfaceHit& hit, Vector3f w, const SampledWavelengths& lambda) const override {
        if (alpha_ && masked(hit.p, hit.n, hit.uv)) return {};
        return emitted(hit.n, w, lambda);
    }
    // Φ = π A L for a one-sided Lambertian emitter, twice that for a two-sided one.
    Power3 power() const override;
    AreaPdf pdf_le_position(const SurfaceHit&) const override { return AreaPdf(1 / shape_->area()); }
    // A point uniform by area, a cosine-weighted direction about its normal (either side with
    // probability 1/2 when two-sided): flux = L cos θ / (p_A · cos θ / π) = π L / p_A (× 2 two-sided).
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    // 1 / A and the cosine-weighted density about n (halved and on either side when two-sided).
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    Radiance3 emitted(Normal3f n, Vector3f w, const SampledWavelengths& lambda) const {
        if (!two_sided_ && dot(n, w) <= 0) return {};
        return Radiance3(radiance_.at(lambda));
    }
    const AreaShape* shape() const { return shape_; }
    bool two_sided() const { return two_sided_; }

private:
    const AreaShape* shape_;
    Emission radiance_;
    bool two_sided_;
    const FloatTexture* alpha_ = nullptr;
};

} // namespace illum
