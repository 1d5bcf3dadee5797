#include "illum/geometry/sphere.h"

#include <algorithm>

#include "illum/math/fast_trig.h"
#include "illum/math/frame.h"

namespace illum {

SphereShape::SphereShape(const Transform& world_from_object, float radius, float zmin, float zmax,
                         float phimax, bool flip_normal)
    : AnalyticShape(world_from_object, flip_normal), radius_(radius),
      zmin_(std::clamp(double(std::min(zmin, zmax)), -radius_, radius_)),
      zmax_(std::clamp(double(std::max(zmin, zmax)), -radius_, radius_)),
      theta_zmin_(std::acos(std::clamp(zmin_ / radius_, -1.0, 1.0))),
      theta_zmax_(std::acos(std::clamp(zmax_ / radius_, -1.0, 1.0))),
      phimax_(std::clamp(double(phimax), 0.0, 2 * kPiD)) {
    full_ = zmin_ <= -radius_ && zmax_ >= radius_ && phimax_ >= 2 * kPiD;
    center_ = to_world(Vec3d{}, &center_error_);
    const Matrix4& m = world_from_object.matrix();
    center_d_ = {m(0, 3), m(1, 3), m(2, 3)};
    world_radius_d_ = scale() * radius_;
    world_radius_ = float(world_radius_d_);
    init_area();
}

SphereShape::SphereShape(Point3f center, float radius, bool flip_normal)
    : SphereShape(Transform::translate(Vector3f(center)), radius, -radius, radius, 2 * kPi, flip_normal) {}

// |o + t d|² = r²: a t² + 2 b t + c = 0 with a = d·d, b = o·d, c = o·o - r². The discriminant
// b² - a c = a (r² - |o - (b/a) d|²) is formed from the ray's distance to the centre, which does not
// cancel as b² - a c does for distant origins (Haines et al., Ray Tracing Gems ch. 7, 2019).
namespace {
int sphere_roots(Vec3d o, Vec3d d, double radius, double t[2]) {
    double a = dot(d, d), b = dot(o, d), c = dot(o, o) - radius * radius;
    if (a == 0) return 0;
    Vec3d f = o - d * (b / a);
    double disc = a * (radius * radius - dot(f, f));
    return solve_quadratic(a, b, c, disc, t);
}
} // namespace

int SphereShape::roots(Vec3d o, Vec3d d, double t[2]) const { return sphere_roots(o, d, radius_, t); }

// A round sphere is the world sphere about the transformed origin with radius scale × r, and the roots of
// o + t d with it are those of the object-space ray: |M^-1 (o + t d)| = r is |o + t d - c| = s r for a
// similarity M. Under a translation the operations are the object space's, bit for bit.
int SphereShape::world_roots(const Ray& ray, double t[2]) const {
    if (!is_round()) return -1;
    Vec3d o{double(ray.o.x) - center_d_.x, double(ray.o.y) - center_d_.y, double(ray.o.z) - center_d_.z};
    return sphere_roots(o, Vec3d{ray.d.x, ray.d.y, ray.d.z}, world_radius_d_, t);
}

bool SphereShape::inside_clip(Vec3d p) const {
    if ((zmin_ > -radius_ && p.z < zmin_) || (zmax_ < radius_ && p.z > zmax_)) return false;
    return phimax_ >= 2 * kPiD || azimuth(p.x, p.y) <= phimax_;
}

namespace {
// The unit outward normal at the sphere point nearest p (+z for the centre itself).
Vec3d normal_towards(Vec3d p) {
    double len = length(p);
    return len > 0 ? p * (1 / len) : Vec3d{0, 0, 1};
}
} // namespace

AnalyticShape::SurfacePoint SphereShape::surface_at(Vec3d p) const {
    SurfacePoint s;
    s.n = normal_towards(p);
    s.p = s.n * radius_;
    double phi = azimuth(s.p.x, s.p.y), theta = std::acos(std::clamp(s.n.z, -1.0, 1.0));
    s.uv = {float(phi / phimax_), float((theta - theta_zmin_) / (theta_zmax_ - theta_zmin_))};
    s.dpdu = Vec3d{-s.p.y, s.p.x, 0} * phimax_;
    return s;
}

// pbrt-v4's ∂p/∂v for v = (θ - θ(zmin)) / (θ(zmax) - θ(zmin)); n = p / r, so ∂n/∂u = ∂p/∂u / r and
// ∂n/∂v = ∂p/∂v / r (what the Weingarten equations give on a sphere).
AnalyticShape::SecondPartials SphereShape::partials_at(const SurfacePoint& s) const {
    double rho = std::sqrt(s.p.x * s.p.x + s.p.y * s.p.y), cos_phi = rho > 0 ? s.p.x / rho : 1,
           sin_phi = rho > 0 ? s.p.y / rho : 0;
    double sin_theta = std::sqrt(std::max(0.0, 1 - s.n.z * s.n.z));
    Vec3d dpdv = Vec3d{s.p.z * cos_phi, s.p.z * sin_phi, -radius_ * sin_theta} * (theta_zmax_ - theta_zmin_);
    return {dpdv, s.dpdu * (1 / radius_), dpdv * (1 / radius_)};
}

// Archimedes: the area of a sphere between two planes is 2π r h, so z uniform in [zmin, zmax] and φ
// uniform in [0, φmax] is uniform by area; the area is φmax r (zmax - zmin) (PBR 4th ed. §6.2.3).
Vec3d SphereShape::sample_object(Point2f u) const {
    double z = zmin_ + u.x * (zmax_ - zmin_), phi = u.y * phimax_;
    double rho = std::sqrt(std::max(0.0, radius_ * radius_ - z * z));
    return {rho * std::cos(phi), rho * std::sin(phi), z};
}

double SphereShape::object_area() const { return phimax_ * radius_ * (zmax_ - zmin_); }

Bounds3f SphereShape::object_bounds() const {
    Bounds3f b;
    b.extend(Point3f(float(-radius_), float(-radius_), float(zmin_)));
    b.extend(Point3f(float(radius_), float(radius_), float(zmax_)));
    return b;
}

bool SphereShape::cone_sampling(Point3f p) const {
    if (!is_round()) return false;
    float r = world_radius();
    return distance_squared(p, center()) > r * r * 1.0001f;
}

std::optional<ShapeSample> SphereShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    if (!cone_sampling(ctx.p)) return AreaShape::sample(ctx, u);
    Point3f c = center();
    float dc2 = distance_squared(ctx.p, c), r2 = sqr(world_radius());

    // Cone of directions that hit the sphere: sin θmax = r / d_c (PBR 4th ed. §6.2.4).
    float sin2_max = r2 / dc2, cos_max = safe_sqrt(1 - sin2_max), one_minus_cos_max = 1 - cos_max;
    float cos_theta = (cos_max - 1) * u.x + 1;
    float sin2_theta = 1 - cos_theta * cos_theta;
    if (sin2_max < 0.00068523f) { // θmax below ~1.5°: Taylor forms keep precision
        sin2_theta = sin2_max * u.x;
        cos_theta = std::sqrt(1 - sin2_theta);
        one_minus_cos_max = sin2_max / 2;
    }
    // The point on the sphere: angle α at the centre from the direction towards the receiver.
    float cos_alpha = sin2_theta / std::sqrt(sin2_max) + cos_theta * safe_sqrt(1 - sin2_theta / sin2_max);
    float sin_alpha = std::clamp(safe_sqrt(1 - cos_alpha * cos_alpha), 0.0f, 1.0f);
    cos_alpha = std::clamp(cos_alpha, -1.0f, 1.0f);
    float sin_phi, cos_phi;
    fast_sincos_2pi(u.y, &sin_phi, &cos_phi); // φ = 2π u.y
    Frame frame = Frame::from_z(normalize(c - ctx.p));
    // +z of the frame points from the receiver to the centre; the point faces the receiver, at -z: its
    // outward normal is -(sin α cos φ, sin α sin φ, cos α) in the frame.
    Vector3f n_world = frame.to_world(Vector3f{-sin_alpha * cos_phi, -sin_alpha * sin_phi, -cos_alpha});
    // Uniform over the cone's solid angle 2π (1 - cos θmax).
    SolidAnglePdf pdf(1 / (2 * kPi * one_minus_cos_max));
    auto s = seen_from(ctx.p, world_point(n_world), pdf);
    if (s && ctx.uv_needed) s->uv = surface_at(to_object(s->p)).uv; // the same point, uv asked or not
    return s;
}

// The point c + r n of the world sphere (centre c, radius r) in the direction n, its error bound and its
// oriented normal: the error of the centre's transform, then of r n and of the sum (one rounding each)
// and of n's length after normalising (a few ulp), all within γ6 (|c| + |r n|).
ShapePoint SphereShape::world_point(Vector3f n_world) const {
    Vector3f n = normalize(n_world);
    Vector3f d = n * world_radius_;
    ShapePoint s;
    s.p = center_ + d;
    s.p_error = center_error_ + (abs(Vector3f(center_)) + abs(d)) * gamma_bound(6);
    s.n = Normal3f(flip_normal() ? -n : n);
    return s;
}

SolidAnglePdf SphereShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                               Normal3f n_hit) const {
    if (!cone_sampling(ctx.p)) return AnalyticShape::pdf(ctx, wi, p_hit, n_hit);
    float sin2_max = sqr(world_radius()) / distance_squared(ctx.p, center());
    float one_minus_cos_max = 1 - safe_sqrt(1 - sin2_max);
    if (sin2_max < 0.00068523f) one_minus_cos_max = sin2_max / 2;
    return SolidAnglePdf(1 / (2 * kPi * one_minus_cos_max));
}

} // namespace illum
