#include "illum/geometry/disk.h"

#include "illum/math/warp.h"

namespace illum {

DiskShape::DiskShape(const Transform& world_from_object, float height, float radius, float inner_radius,
                     bool flip_normal)
    : world_from_object_(world_from_object), object_from_world_(world_from_object.inverse()), height_(height),
      radius_(radius), inner_radius_(inner_radius), flip_(flip_normal) {
    // Area under an affine map scales by |T(x) × T(y)|.
    Vector3f ex = world_from_object_(Vector3f{1, 0, 0}), ey = world_from_object_(Vector3f{0, 1, 0});
    area_ = kPi * (radius_ * radius_ - inner_radius_ * inner_radius_) * length(cross(ex, ey));
    normal_ = normalize(world_from_object_(Normal3f{0, 0, 1}));
    if (flip_) normal_ = -normal_;
}

Bounds3f DiskShape::bounds() const {
    Bounds3f b;
    for (float x : {-radius_, radius_})
        for (float y : {-radius_, radius_}) b.extend(world_from_object_(Point3f{x, y, height_}));
    return b;
}

std::optional<float> DiskShape::intersect(const Ray& ray) const {
    Point3f o = object_from_world_(ray.o);
    Vector3f d = object_from_world_(ray.d);
    if (d.z == 0) return std::nullopt;
    float t = (height_ - o.z) / d.z;
    if (!(t > 0 && t < ray.tmax)) return std::nullopt;
    Point3f p = o + d * t;
    float r2 = p.x * p.x + p.y * p.y;
    if (r2 > radius_ * radius_ || r2 < inner_radius_ * inner_radius_) return std::nullopt;
    return t;
}

void DiskShape::fill_hit(float t, const Ray& ray, SurfaceHit* hit) const {
    Point3f po = object_from_world_(ray.o) + object_from_world_(ray.d) * t;
    po.z = height_; // exactly on the plane in object space
    hit->p = world_from_object_(po);
    hit->p_error = abs(hit->p) * gamma_bound(6) + abs(Vector3f(po)) * gamma_bound(3);
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = normal_;
    hit->ns = normal_;
    float r = std::sqrt(po.x * po.x + po.y * po.y);
    float phi = std::atan2(po.y, po.x);
    if (phi < 0) phi += 2 * kPi;
    hit->uv = {phi / (2 * kPi), (radius_ - r) / (radius_ - inner_radius_)};
    hit->dpdu = world_from_object_(Vector3f{-po.y, po.x, 0} * (2 * kPi));
}

ShapeSample DiskShape::sample_area(Point2f u) const {
    // Uniform over the annulus: r = sqrt(ri² + u (ro² - ri²)).
    Point2f d = sample_uniform_disk_concentric(u);
    float rho2 = d.x * d.x + d.y * d.y;
    float r =
        std::sqrt(inner_radius_ * inner_radius_ + rho2 * (radius_ * radius_ - inner_radius_ * inner_radius_));
    float scale = rho2 > 0 ? r / std::sqrt(rho2) : 0;
    Point3f po{d.x * scale, d.y * scale, height_};
    ShapeSample s;
    s.p = world_from_object_(po);
    s.p_error = abs(s.p) * gamma_bound(6);
    s.n = normal_;
    float phi = std::atan2(po.y, po.x);
    if (phi < 0) phi += 2 * kPi;
    s.uv = {phi / (2 * kPi), (radius_ - r) / std::max(radius_ - inner_radius_, 1e-20f)};
    s.pdf = 1 / area_;
    return s;
}

} // namespace illum
