#include "illum/light/diffuse_area_light.h"

namespace illum {

std::optional<LightLiSample> DiffuseAreaLight::sample_li(const LightSampleContext& ctx, Point2f u) const {
    auto ss = shape_->sample({ctx.p, ctx.p_error, ctx.n}, u);
    if (!ss || !(ss->pdf > 0)) return std::nullopt;
    Vector3f d = ss->p - ctx.p;
    float d2 = length_squared(d);
    if (d2 == 0) return std::nullopt;
    Vector3f wi = d / std::sqrt(d2);
    Radiance3 l = emitted(ss->n, -wi);
    if (l.is_black()) return std::nullopt;
    SolidAnglePdf pdf(ss->pdf);
    return LightLiSample{wi, l, biradiance(l, pdf), pdf, ss->p, ss->p_error, ss->n, false};
}

SolidAnglePdf DiffuseAreaLight::pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const {
    if (!hit) return SolidAnglePdf(0);
    return SolidAnglePdf(shape_->pdf({ctx.p, ctx.p_error, ctx.n}, wi, hit->p, hit->n));
}

Power3 DiffuseAreaLight::power() const {
    return Power3(lambertian_exitance(radiance_).rgb * shape_->area() * (two_sided_ ? 2.0f : 1.0f));
}

} // namespace illum
