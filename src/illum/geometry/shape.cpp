#include "illum/geometry/shape.h"

#include <cmath>

namespace illum {

std::optional<ShapeSample> AreaShape::area_to_solid_angle(const ShapeSampleContext& ctx, AreaShapeSample s) {
    Vector3f wi = s.p - ctx.p;
    float d2 = length_squared(wi);
    if (d2 == 0) return std::nullopt;
    wi = wi / std::sqrt(d2);
    float cos_l = abs_dot(s.n, -wi);
    if (cos_l == 0) return std::nullopt;
    SolidAnglePdf pdf = to_solid_angle(s.pdf, area_per_solid_angle(d2, cos_l));
    if (!pdf.is_finite()) return std::nullopt;
    return ShapeSample{s, pdf, wi};
}

SolidAnglePdf AreaShape::area_pdf_to_solid_angle(AreaPdf pdf_area, Point3f p_ref, Point3f p_hit,
                                                 Normal3f n_hit, Vector3f wi) {
    float d2 = distance_squared(p_ref, p_hit);
    float cos_l = abs_dot(n_hit, wi);
    if (cos_l == 0) return SolidAnglePdf(0);
    SolidAnglePdf pdf = to_solid_angle(pdf_area, d2, cos_l);
    return pdf.is_finite() ? pdf : SolidAnglePdf(0);
}

std::optional<ShapeSample> AreaShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    return area_to_solid_angle(ctx, sample_area(u));
}

SolidAnglePdf AreaShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                             Normal3f n_hit) const {
    return area_pdf_to_solid_angle(AreaPdf(1 / area()), ctx.p, p_hit, n_hit, wi);
}

} // namespace illum
