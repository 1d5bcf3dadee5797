#include "illum/light/projection_light.h"

#include <cmath>

#include "illum/light/light_image.h"
#include "illum/light/point_source.h"
#include "illum/radiometry/uplift.h"

namespace illum {

namespace {

// pbrt-v4 drops directions closer to the plane z = 0 than its near plane ("hither", 10⁻³).
constexpr float kHither = 1e-3f;

double corner(double a, double b) { return std::atan(a * b / std::sqrt(1 + a * a + b * b)); }

} // namespace

ProjectionFrustum::ProjectionFrustum(int width, int height, float fov_degrees) {
    float t = std::tan(fov_degrees * (kPi / 180) / 2);
    float aspect = float(width) / float(height);
    sx = aspect > 1 ? t * aspect : t;
    sy = aspect > 1 ? t : t / aspect;
}

double plane_rectangle_solid_angle(double a0, double a1, double b0, double b1) {
    return corner(a1, b1) - corner(a0, b1) - corner(a1, b0) + corner(a0, b0);
}

double projection_power_normalisation(const Image& image, float fov_degrees) {
    ProjectionFrustum fr(image.width(), image.height(), fov_degrees);
    double sum = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            double a = fr.a((x + 0.5f) / float(image.width())), b = fr.b((y + 0.5f) / float(image.height()));
            double cos_theta = 1 / std::sqrt(1 + a * a + b * b);
            sum += double(image(x, y).luminance()) * cos_theta * cos_theta * cos_theta;
        }
    return 4.0 * fr.sx * fr.sy * sum / double(image.pixel_count());
}

ProjectionLight::ProjectionLight(const Transform& world_from_light, const Image& image, float scale,
                                 float fov_degrees)
    : Light(LightType::DeltaPosition), position_(world_from_light(Point3f{0, 0, 0})),
      world_from_light_(world_from_light), light_from_world_(world_from_light.inverse()), image_(image),
      scale_(scale), frustum_(image.width(), image.height(), fov_degrees) {
    const int w = image_.width(), h = image_.height();
    std::vector<float> weights(image_.pixel_count());
    double sum[3] = {};
    for (int y = 0; y < h; ++y) {
        double b0 = frustum_.b(float(y + 1) / float(h)), b1 = frustum_.b(float(y) / float(h));
        for (int x = 0; x < w; ++x) {
            double a0 = frustum_.a(float(x) / float(w)), a1 = frustum_.a(float(x + 1) / float(w));
            double omega = plane_rectangle_solid_angle(a0, a1, b0, b1);
            const Color3& l = image_(x, y);
            for (int c = 0; c < 3; ++c) sum[c] += double(l[c]) * omega;
            weights[std::size_t(y) * std::size_t(w) + std::size_t(x)] = float(l.average() * omega);
        }
    }
    power_ = Color3(float(sum[0]), float(sum[1]), float(sum[2])) * scale_;
    distribution_ = Distribution2D(weights, w, h);
}

std::optional<Point2f> ProjectionLight::image_uv(Vector3f w_world) const {
    Vector3f l = normalize(light_from_world_(w_world));
    if (l.z < kHither) return std::nullopt;
    float a = l.x / l.z, b = l.y / l.z;
    // pbrt-v4's Inside() admits the window's edges.
    if (!(std::abs(a) <= frustum_.sx && std::abs(b) <= frustum_.sy)) return std::nullopt;
    return Point2f{(a / frustum_.sx + 1) / 2, (1 - b / frustum_.sy) / 2};
}

Intensity3 ProjectionLight::intensity(Vector3f w_world, const SampledWavelengths& lambda) const {
    auto uv = image_uv(w_world);
    if (!uv) return {};
    const Color3& l = lookup_nearest(image_, *uv);
    if (l.is_black()) return {};
    return Intensity3(uplift_illuminant(l, lambda) * scale_);
}

std::optional<LightLiSample> ProjectionLight::sample_li(const LightSampleContext& ctx, Point2f,
                                                        const SampledWavelengths& lambda) const {
    return point_source_li(position_, ctx.p, [&](Vector3f w) { return intensity(w, lambda); });
}

std::optional<LightLeSample> ProjectionLight::sample_le(Point2f, Point2f u2,
                                                        const SampledWavelengths& lambda) const {
    float pdf_uv = 0;
    Point2f uv = distribution_.sample(u2, &pdf_uv);
    if (!(pdf_uv > 0)) return std::nullopt;
    float a = frustum_.a(uv.x), b = frustum_.b(uv.y);
    float r2 = 1 + a * a + b * b;
    Vector3f w = normalize(world_from_light_(Vector3f{a, b, 1}));
    // Density per unit plane area pdf_uv / (4 sx sy), per steradian times dA/dω = r³.
    SolidAnglePdf pdf_dir(pdf_uv / (4 * frustum_.sx * frustum_.sy) * r2 * std::sqrt(r2));
    const Color3& l = lookup_nearest(image_, uv);
    Intensity3 i(uplift_illuminant(l, lambda) * scale_);
    return LightLeSample{Ray{position_, w}, {}, {}, AreaPdf(1), pdf_dir, i / pdf_dir, position_, {}};
}

void ProjectionLight::pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = AreaPdf(1);
    auto uv = image_uv(ray.d);
    if (!uv) {
        *dir = SolidAnglePdf(0);
        return;
    }
    float a = frustum_.a(uv->x), b = frustum_.b(uv->y);
    float r2 = 1 + a * a + b * b;
    *dir = SolidAnglePdf(distribution_.pdf(*uv) / (4 * frustum_.sx * frustum_.sy) * r2 * std::sqrt(r2));
}

} // namespace illum

namespace illum {

std::optional<LightBounds> ProjectionLight::bounds() const {
    const double omega = plane_rectangle_solid_angle(-frustum_.sx, frustum_.sx, -frustum_.sy, frustum_.sy);
    LightBounds b = point_bounds(position_, float(4 * double(kPi) * double(power_.luminance()) / omega));
    b.w = normalize(world_from_light_(Vector3f{0, 0, 1}));
    b.cos_theta_o = 1;
    // The frustum's corners are the directions farthest from the axis (each carried to the world: the
    // light's transform may shear).
    float cos_e = 1;
    for (float sa : {-1.0f, 1.0f})
        for (float sb : {-1.0f, 1.0f})
            cos_e = std::min(
                cos_e,
                dot(b.w, normalize(world_from_light_(Vector3f{sa * frustum_.sx, sb * frustum_.sy, 1}))));
    b.cos_theta_e = std::min(cos_e, 0.999f);
    return b;
}

} // namespace illum
