#include "illum/light/diffuse_area_light.h"

#include <cstring>

#include "illum/light/light_image.h"
#include "illum/math/frame.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/radiometry/uplift.h"

namespace illum {

DiffuseAreaLight::DiffuseAreaLight(const AreaShape* shape, std::shared_ptr<const Image> image, float scale,
                                   bool two_sided)
    : Light(LightType::Area), shape_(shape), radiance_(Color3(scale)), two_sided_(two_sided),
      image_(std::move(image)), image_scale_(scale), image_integral_(image_integral(*shape, *image_)) {}

Radiance3 DiffuseAreaLight::emitted(Normal3f n, Point2f uv, Vector3f w,
                                    const SampledWavelengths& lambda) const {
    if (!two_sided_ && dot(n, w) <= 0) return {};
    if (!image_) return Radiance3(radiance_.at(lambda));
    Color3 rgb = lookup_bilinear(*image_, Point2f{uv.x, 1 - uv.y});
    if (rgb.is_black()) return {};
    return Radiance3(uplift_illuminant(rgb, lambda) * image_scale_);
}

Color3 image_integral(const AreaShape& shape, const Image& image) {
    auto integrate = [&](int n, Point2f* uv_min, Point2f* uv_max) {
        double sum[3] = {};
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                AreaShapeSample s = shape.sample_area({(i + 0.5f) / float(n), (j + 0.5f) / float(n)});
                if (!(s.pdf > AreaPdf(0))) continue;
                Color3 l = lookup_bilinear(image, Point2f{s.uv.x, 1 - s.uv.y});
                for (int c = 0; c < 3; ++c) sum[c] += double(l[c]) / double(s.pdf.value);
                if (uv_min) {
                    *uv_min = Point2f{std::min(uv_min->x, s.uv.x), std::min(uv_min->y, s.uv.y)};
                    *uv_max = Point2f{std::max(uv_max->x, s.uv.x), std::max(uv_max->y, s.uv.y)};
                }
            }
        double nn = double(n) * n;
        return Color3(float(sum[0] / nn), float(sum[1] / nn), float(sum[2] / nn));
    };
    const int coarse = 4;
    Point2f lo{kInfinity, kInfinity}, hi{-kInfinity, -kInfinity};
    Color3 estimate = integrate(coarse, &lo, &hi);
    if (!(hi.x >= lo.x)) return estimate;
    // The texels the uv box spans (its width grows by one stratum: the samples are stratum centres).
    double span_u = std::min(1.0, double(hi.x - lo.x) * coarse / (coarse - 1)),
           span_v = std::min(1.0, double(hi.y - lo.y) * coarse / (coarse - 1));
    double texels = (span_u * image.width() + 1) * (span_v * image.height() + 1);
    int n = std::clamp(int(std::ceil(4 * std::sqrt(texels))), 8, 256);
    return integrate(n, nullptr, nullptr);
}

bool DiffuseAreaLight::masked(Point3f p, Normal3f n, Point2f uv) const {
    if (!alpha_) return false;
    SurfaceHit h;
    h.p = p;
    h.n = n;
    h.ns = n;
    h.uv = uv;
    float a = alpha_->evaluate(h);
    if (a >= 1) return false;
    if (!(a > 0)) return true;
    std::uint32_t x, y, z;
    std::memcpy(&x, &p.x, 4);
    std::memcpy(&y, &p.y, 4);
    std::memcpy(&z, &p.z, 4);
    return float(hash(x, y, z) >> 40) * 0x1p-24f >= a;
}

std::optional<LightLiSample> DiffuseAreaLight::sample_li(const LightSampleContext& ctx, Point2f u,
                                                         const SampledWavelengths& lambda) const {
    // uv is read by the emission image and the alpha texture only.
    auto ss = shape_->sample({ctx.p, ctx.p_error, ctx.n, image_ || alpha_}, u);
    if (!ss || !(ss->pdf > SolidAnglePdf(0))) return std::nullopt;
    const Vector3f wi = ss->wi;
    Radiance3 l = emitted(ss->n, ss->uv, -wi, lambda);
    if (l.is_black() || masked(ss->p, ss->n, ss->uv)) return std::nullopt;
    return LightLiSample{wi, l, biradiance(l, ss->pdf), ss->pdf, ss->p, ss->p_error, ss->n, false};
}

SolidAnglePdf DiffuseAreaLight::pdf_li(const LightSampleContext& ctx, Vector3f wi,
                                       const SurfaceHit* hit) const {
    if (!hit) return SolidAnglePdf(0);
    return shape_->pdf({ctx.p, ctx.p_error, ctx.n}, wi, hit->p, hit->n);
}

Power3 DiffuseAreaLight::power() const {
    if (image_)
        return Power3(SampledSpectrum(image_integral_ * (image_scale_ * kPi * (two_sided_ ? 2.0f : 1.0f))));
    return lambertian_exitance(Radiance3(radiance_.rgb_value())) * Area(shape_->area()) *
           (two_sided_ ? 2.0f : 1.0f);
}

std::optional<LightBounds> DiffuseAreaLight::bounds() const {
    DirectionCone normals = shape_->normal_bounds();
    LightBounds b;
    b.bounds = shape_->bounds();
    b.w = normals.w;
    b.cos_theta_o = normals.cos_theta;
    b.cos_theta_e = 0;
    b.two_sided = two_sided_;
    float one_side = power().rgb().luminance() / (two_sided_ ? 2.0f : 1.0f); // π L A
    b.phi = 2 * one_side;
    return b;
}

std::optional<LightLeSample> DiffuseAreaLight::sample_le(Point2f u1, Point2f u2,
                                                         const SampledWavelengths& lambda) const {
    AreaShapeSample ss = shape_->sample_area(u1);
    if (!(ss.pdf > AreaPdf(0)) || masked(ss.p, ss.n, ss.uv)) return std::nullopt;
    Vector3f n(ss.n);
    float side_pmf = 1;
    if (two_sided_) {
        // Reuse u2.x for the side: remap it to [0, 1) within the half it fell in.
        side_pmf = 0.5f;
        if (u2.x < 0.5f) {
            u2.x = std::min(u2.x * 2, 0x1.fffffep-1f);
        } else {
            u2.x = std::min((u2.x - 0.5f) * 2, 0x1.fffffep-1f);
            n = -n;
        }
    }
    Vector3f w_local = sample_cosine_hemisphere(u2);
    float cos_theta = w_local.z;
    if (!(cos_theta > 0)) return std::nullopt;
    Vector3f w = Frame::from_z(n).to_world(w_local);
    SolidAnglePdf pdf_dir(cosine_hemisphere_pdf(cos_theta) * side_pmf);
    AreaPdf pdf_pos = ss.pdf;
    Point3f o = offset_ray_origin(ss.p, ss.p_error, ss.n, w);
    Radiance3 l = emitted(ss.n, ss.uv, w, lambda);
    return LightLeSample{Ray{o, w}, ss.n,      l, pdf_pos, pdf_dir, l * cos_theta / pdf_pos / pdf_dir,
                         ss.p,      ss.p_error};
}

void DiffuseAreaLight::pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = shape_->area_pdf(ray.o);
    float cos_theta = dot(Vector3f(n), ray.d) / length(ray.d);
    if (two_sided_)
        *dir = SolidAnglePdf(cosine_hemisphere_pdf(std::abs(cos_theta)) * 0.5f);
    else
        *dir = SolidAnglePdf(cos_theta > 0 ? cosine_hemisphere_pdf(cos_theta) : 0.0f);
}

} // namespace illum
