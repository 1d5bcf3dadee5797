#include "illum/geometry/sphere.h"

#include "illum/math/frame.h"
#include "illum/math/warp.h"

namespace illum {

Bounds3f SphereShape::bounds() const {
    Bounds3f b;
    Vector3f r{radius_, radius_, radius_};
    b.extend(center_ - r);
    b.extend(center_ + r);
    return b;
}

void SphereShape::reproject(Point3f* p, Vector3f* err) const {
    Vector3f d = *p - center_;
    float len = length(d);
    if (len > 0) d = d * (radius_ / len);
    *p = center_ + d;
    *err = abs(d) * gamma_bound(5) + abs(Vector3f(center_)) * gamma_bound(1);
}

Normal3f SphereShape::outward(Point3f p) const {
    Normal3f n = normalize(Normal3f(p - center_));
    return flip_ ? -n : n;
}

Point2f SphereShape::uv_at(Point3f p) const {
    Vector3f d = normalize(p - center_);
    return {spherical_phi(d) / (2 * kPi), spherical_theta(d) / kPi};
}

void SphereShape::fill_hit(float t, const Ray& ray, SurfaceHit* hit) const {
    Point3f p = ray(t);
    reproject(&p, &hit->p_error);
    hit->p = p;
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = outward(p);
    hit->ns = hit->n;
    hit->uv = uv_at(p);
    Vector3f d = p - center_;
    hit->dpdu = Vector3f{-d.y, d.x, 0} * (2 * kPi);
}

ShapeSample SphereShape::sample_area(Point2f u) const {
    ShapeSample s;
    s.p = center_ + sample_uniform_sphere(u) * radius_;
    reproject(&s.p, &s.p_error);
    s.n = outward(s.p);
    s.uv = uv_at(s.p);
    s.pdf = 1 / area();
    return s;
}

std::optional<ShapeSample> SphereShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    float dc2 = distance_squared(ctx.p, center_);
    float r2 = radius_ * radius_;
    if (dc2 <= r2 * 1.0001f) return AreaShape::sample(ctx, u);

    // Cone of directions that hit the sphere: sin θmax = r / d_c.
    float sin2_max = r2 / dc2, cos_max = safe_sqrt(1 - sin2_max), one_minus_cos_max = 1 - cos_max;
    float cos_theta = (cos_max - 1) * u.x + 1;
    float sin2_theta = 1 - cos_theta * cos_theta;
    if (sin2_max < 0.00068523f) { // θmax below ~1.5°: Taylor forms keep precision
        sin2_theta = sin2_max * u.x;
        cos_theta = std::sqrt(1 - sin2_theta);
        one_minus_cos_max = sin2_max / 2;
    }
    // The point on the sphere: angle α at the center from the direction towards the receiver.
    float cos_alpha = sin2_theta / std::sqrt(sin2_max) + cos_theta * safe_sqrt(1 - sin2_theta / sin2_max);
    float sin_alpha = safe_sqrt(1 - cos_alpha * cos_alpha);
    float phi = u.y * 2 * kPi;
    Frame frame = Frame::from_z(normalize(center_ - ctx.p));
    Vector3f w = spherical_direction(sin_alpha, cos_alpha, phi);
    // w is in a frame whose +z points from the center towards... the receiver is at -z, so negate.
    Vector3f n_world = frame.to_world(Vector3f{-w.x, -w.y, -w.z});
    ShapeSample s;
    s.p = center_ + n_world * radius_;
    reproject(&s.p, &s.p_error);
    s.n = flip_ ? Normal3f(-n_world) : Normal3f(n_world);
    s.uv = uv_at(s.p);
    s.pdf = 1 / (2 * kPi * one_minus_cos_max);
    return s;
}

float SphereShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit, Normal3f n_hit) const {
    float dc2 = distance_squared(ctx.p, center_);
    float r2 = radius_ * radius_;
    if (dc2 <= r2 * 1.0001f) return AreaShape::pdf(ctx, wi, p_hit, n_hit);
    float sin2_max = r2 / dc2, cos_max = safe_sqrt(1 - sin2_max), one_minus_cos_max = 1 - cos_max;
    if (sin2_max < 0.00068523f) one_minus_cos_max = sin2_max / 2;
    return 1 / (2 * kPi * one_minus_cos_max);
}

} // namespace illum
