#include "illum/geometry/shape.h"

#include <cmath>

namespace illum {

std::optional<ShapeSample> AreaShape::area_to_solid_angle(const ShapeSampleContext& ctx, ShapeSample s) {
    Vector3f wi = s.p - ctx.p;
    float d2 = length_squared(wi);
    if (d2 == 0) return std::nullopt;
    wi = wi / std::sqrt(d2);
    float cos_l = abs_dot(s.n, -wi);
    if (cos_l == 0) return std::nullopt;
    s.pdf *= d2 / cos_l;
    if (!std::isfinite(s.pdf)) return std::nullopt;
    return s;
}

float AreaShape::area_pdf_to_solid_angle(float pdf_area, Point3f p_ref, Point3f p_hit, Normal3f n_hit,
                                         Vector3f wi) {
    float d2 = distance_squared(p_ref, p_hit);
    float cos_l = abs_dot(n_hit, wi);
    if (cos_l == 0) return 0;
    float pdf = pdf_area * d2 / cos_l;
    return std::isfinite(pdf) ? pdf : 0.0f;
}

std::optional<ShapeSample> AreaShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    return area_to_solid_angle(ctx, sample_area(u));
}

float AreaShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit, Normal3f n_hit) const {
    return area_pdf_to_solid_angle(1 / area(), ctx.p, p_hit, n_hit, wi);
}

} // namespace illum
