#include "illum/light/portal_environment_light.h"

#include <cmath>

#include <fmt/format.h>

#include "illum/light/light_image.h"
#include "illum/radiometry/uplift.h"

namespace illum {

namespace {

double psa_corner(double a, double b) {
    double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b);
    return 0.5 * (sa * std::atan2(sb * ca, cb) + sb * std::atan2(sa * cb, ca));
}

// The rectified resolution: a square (equal-area) map keeps its own, as pbrt-v4 does; another layout gets
// about π over its mean texel angle √(4π / texels), so the rectified texels are no coarser than the input's.
int rectified_resolution(const EnvironmentMap& map) {
    if (map.layout() == EnvLayout::Octahedral) return std::max(map.width(), 8);
    double texels = double(map.width()) * map.height();
    return std::clamp(int(std::ceil(std::sqrt(kPiD * texels) / 2)), 8, 4096);
}

} // namespace

std::string portal_shape_problem(const std::array<Point3f, 4>& p) {
    for (const Point3f& q : p)
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            return "a corner is not finite";
    Vector3f e01 = p[1] - p[0], e12 = p[2] - p[1], e32 = p[2] - p[3], e03 = p[3] - p[0];
    for (Vector3f e : {e01, e12, e32, e03})
        if (!(length(e) > 0)) return "two corners coincide";
    e01 = normalize(e01), e12 = normalize(e12), e32 = normalize(e32), e03 = normalize(e03);
    if (std::abs(dot(e01, e32) - 1) > 1e-3f || std::abs(dot(e12, e03) - 1) > 1e-3f)
        return "its opposite edges are not parallel";
    if (std::abs(dot(e01, e12)) > 1e-3f || std::abs(dot(e12, e32)) > 1e-3f ||
        std::abs(dot(e32, e03)) > 1e-3f || std::abs(dot(e03, e01)) > 1e-3f)
        return "its edges are not perpendicular";
    return {};
}

double rectified_psa(double a0, double a1, double b0, double b1) {
    return psa_corner(a1, b1) - psa_corner(a0, b1) - psa_corner(a1, b0) + psa_corner(a0, b0);
}

PortalEnvironmentLight::PortalEnvironmentLight(const EnvironmentMap& map, const Transform& world_from_light,
                                               float scale, const std::array<Point3f, 4>& portal)
    : Light(LightType::Infinite), portal_(portal), scale_(std::isfinite(scale) && scale > 0 ? scale : 0.0f) {
    Vector3f x = normalize(portal_[3] - portal_[0]), y = normalize(portal_[1] - portal_[0]);
    frame_ = Frame(x, y, normalize(cross(x, y)));
    width_ = length(portal_[3] - portal_[0]);
    height_ = length(portal_[1] - portal_[0]);
    const int n = rectified_resolution(map);
    image_ = Image(n, n);
    Transform light_from_world = world_from_light.inverse();
    std::vector<float> weights(std::size_t(n) * std::size_t(n));
    double sum[3] = {};
    for (int j = 0; j < n; ++j) {
        double b0 = -kPiD / 2 + kPiD * j / n, b1 = -kPiD / 2 + kPiD * (j + 1) / n;
        for (int i = 0; i < n; ++i) {
            float jac = 0;
            Vector3f w = world_from_image({(i + 0.5f) / float(n), (j + 0.5f) / float(n)}, &jac);
            Vector3f d = light_from_world(w);
            Color3 l = map.lookup(d / length(d));
            image_(i, j) = l;
            weights[std::size_t(j) * std::size_t(n) + std::size_t(i)] = l.average() * jac;
            double psa = rectified_psa(-kPiD / 2 + kPiD * i / n, -kPiD / 2 + kPiD * (i + 1) / n, b0, b1);
            for (int c = 0; c < 3; ++c) sum[c] += double(l[c]) * psa;
        }
    }
    double k = double(scale_) * width_ * height_;
    power_ = Color3(float(k * sum[0]), float(k * sum[1]), float(k * sum[2]));
    distribution_ = WindowedDistribution2D(weights, n, n);
}

void PortalEnvironmentLight::preprocess(const Bounds3f& scene_bounds) {
    scene_bounds.bounding_sphere(&scene_center_, &scene_radius_);
}

std::optional<Point2f> PortalEnvironmentLight::image_from_world(Vector3f w_world, float* jacobian) const {
    Vector3f w = frame_.to_local(w_world);
    float len = length(w);
    if (!(len > 0)) return std::nullopt;
    w = w / len;
    if (w.z <= 0) return std::nullopt;
    if (jacobian) *jacobian = kPi * kPi * (1 - w.x * w.x) * (1 - w.y * w.y) / w.z;
    float alpha = std::atan2(w.x, w.z), beta = std::atan2(w.y, w.z);
    return Point2f{std::clamp((alpha + kPi / 2) / kPi, 0.0f, 1.0f),
                   std::clamp((beta + kPi / 2) / kPi, 0.0f, 1.0f)};
}

Vector3f PortalEnvironmentLight::world_from_image(Point2f uv, float* jacobian) const {
    float alpha = -kPi / 2 + uv.x * kPi, beta = -kPi / 2 + uv.y * kPi;
    float sa = std::sin(alpha), ca = std::max(std::cos(alpha), 0.0f), sb = std::sin(beta),
          cb = std::max(std::cos(beta), 0.0f);
    // w ∝ (tan α, tan β, 1), scaled by cos α cos β to stay finite at the edges; |.|² = cα² + cβ² - cα² cβ².
    float q = ca * ca + cb * cb - ca * ca * cb * cb;
    if (!(q > 0)) {
        if (jacobian) *jacobian = 0;
        return frame_.to_world(Vector3f{sa, sb, 0});
    }
    float inv = 1 / std::sqrt(q);
    if (jacobian) *jacobian = kPi * kPi * ca * cb * inv * inv * inv;
    return frame_.to_world(Vector3f{sa * cb * inv, ca * sb * inv, ca * cb * inv});
}

bool PortalEnvironmentLight::window(Point3f p, Point2f* lo, Point2f* hi) const {
    auto a = image_from_world(portal_[0] - p, nullptr), b = image_from_world(portal_[2] - p, nullptr);
    if (!a || !b) return false;
    *lo = Point2f{std::min(a->x, b->x), std::min(a->y, b->y)};
    *hi = Point2f{std::max(a->x, b->x), std::max(a->y, b->y)};
    return true;
}

Radiance3 PortalEnvironmentLight::lookup(Point2f uv, const SampledWavelengths& lambda) const {
    const Color3& l = lookup_nearest(image_, uv);
    if (l.is_black()) return {};
    return Radiance3(uplift_illuminant(l, lambda) * scale_);
}

Radiance3 PortalEnvironmentLight::le(const Ray& ray, const SampledWavelengths& lambda) const {
    auto uv = image_from_world(ray.d, nullptr);
    Point2f lo, hi;
    if (!uv || !window(ray.o, &lo, &hi)) return {};
    if (!(uv->x >= lo.x && uv->x <= hi.x && uv->y >= lo.y && uv->y <= hi.y)) return {};
    return lookup(*uv, lambda);
}

std::optional<LightLiSample> PortalEnvironmentLight::sample_li(const LightSampleContext& ctx, Point2f u,
                                                               const SampledWavelengths& lambda) const {
    Point2f lo, hi;
    if (!window(ctx.p, &lo, &hi)) return std::nullopt;
    float pdf_uv = 0;
    auto uv = distribution_.sample(u, lo, hi, &pdf_uv);
    if (!uv || !(pdf_uv > 0)) return std::nullopt;
    float jac = 0;
    Vector3f wi = world_from_image(*uv, &jac);
    if (!(jac > 0)) return std::nullopt;
    SolidAnglePdf pdf(pdf_uv / jac);
    Radiance3 l = lookup(*uv, lambda);
    if (l.is_black() || !pdf.is_finite()) return std::nullopt;
    return LightLiSample{wi, l, biradiance(l, pdf), pdf, {}, {}, {}, true};
}

SolidAnglePdf PortalEnvironmentLight::pdf_li(const LightSampleContext& ctx, Vector3f wi,
                                             const SurfaceHit*) const {
    float jac = 0;
    auto uv = image_from_world(wi, &jac);
    Point2f lo, hi;
    if (!uv || !(jac > 0) || !window(ctx.p, &lo, &hi)) return SolidAnglePdf(0);
    return SolidAnglePdf(distribution_.pdf(*uv, lo, hi) / jac);
}

std::optional<LightLeSample> PortalEnvironmentLight::sample_le(Point2f u1, Point2f u2,
                                                               const SampledWavelengths& lambda) const {
    if (!(scene_radius_ > 0)) return std::nullopt;
    float pdf_uv = 0;
    auto uv = distribution_.sample(u2, {0, 0}, {1, 1}, &pdf_uv);
    if (!uv || !(pdf_uv > 0)) return std::nullopt;
    float jac = 0;
    Vector3f wi = world_from_image(*uv, &jac);
    if (!(jac > 0)) return std::nullopt;
    Radiance3 l = lookup(*uv, lambda);
    if (l.is_black()) return std::nullopt;
    LightLeSample s = disk_emission(scene_center_, scene_radius_, wi, u1, l, SolidAnglePdf(pdf_uv / jac));
    // Where the photon's line crosses the portal's plane, and whether that is within the portal.
    float denom = dot(s.ray.d, frame_.n);
    if (!(std::abs(denom) > 0)) return std::nullopt;
    float t = dot(portal_[0] - s.ray.o, frame_.n) / denom;
    Point3f q = s.ray.o + s.ray.d * t;
    Vector3f e = q - portal_[0];
    float x = dot(e, frame_.s), y = dot(e, frame_.t);
    if (!(x >= 0 && x <= width_ && y >= 0 && y <= height_)) return std::nullopt;
    s.ray.o = q;
    s.p_surface = q;
    return s;
}

void PortalEnvironmentLight::pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = disk_emission_pdf(scene_radius_);
    float jac = 0;
    auto uv = image_from_world(-ray.d, &jac);
    *dir = SolidAnglePdf(uv && jac > 0 ? distribution_.pdf(*uv, {0, 0}, {1, 1}) / jac : 0.0f);
}

} // namespace illum
