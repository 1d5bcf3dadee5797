#include "illum/geometry/disk.h"

#include <algorithm>

#include "illum/math/warp.h"

namespace illum {

DiskShape::DiskShape(const Transform& world_from_object, float height, float radius, float inner_radius,
                     bool flip_normal, float phimax)
    : AnalyticShape(world_from_object, flip_normal), height_(height), radius_(radius),
      inner_radius_(inner_radius), phimax_(std::clamp(double(phimax), 0.0, 2 * kPiD)) {
    init_area();
}

// The plane z = height: t = (height - o_z) / d_z.
int DiskShape::roots(Vec3d o, Vec3d d, double t[2]) const {
    if (d.z == 0) return 0;
    t[0] = (height_ - o.z) / d.z;
    return 1;
}

bool DiskShape::inside_clip(Vec3d p) const {
    double r2 = p.x * p.x + p.y * p.y;
    if (r2 > radius_ * radius_ || r2 < inner_radius_ * inner_radius_) return false;
    return phimax_ >= 2 * kPiD || azimuth(p.x, p.y) <= phimax_;
}

AnalyticShape::SurfacePoint DiskShape::surface_at(Vec3d p) const {
    SurfacePoint s;
    s.p = {p.x, p.y, height_}; // exactly on the plane
    s.n = {0, 0, 1};
    double rho = std::sqrt(p.x * p.x + p.y * p.y);
    s.uv = {float(azimuth(p.x, p.y) / phimax_), float((radius_ - rho) / (radius_ - inner_radius_))};
    s.dpdu = Vec3d{-p.y, p.x, 0} * phimax_;
    return s;
}

// pbrt-v4: v = (r - ρ) / (r - ri), so ∂p/∂v = (x, y, 0) (ri - r) / ρ; a plane's normal does not change.
AnalyticShape::SecondPartials DiskShape::partials_at(const SurfacePoint& s) const {
    double rho = std::sqrt(s.p.x * s.p.x + s.p.y * s.p.y);
    Vec3d dpdv = rho > 0 ? Vec3d{s.p.x, s.p.y, 0} * ((inner_radius_ - radius_) / rho)
                         : Vec3d{inner_radius_ - radius_, 0, 0};
    return {dpdv, {}, {}};
}

// Uniform over the annular sector: ρ² uniform in [ri², r²], φ uniform in [0, φmax] (the area element is
// ρ dρ dφ = d(ρ²)/2 dφ). The whole annulus keeps the concentric map's lower distortion, its radius
// remapped the same way.
Vec3d DiskShape::sample_object(Point2f u) const {
    double ri2 = inner_radius_ * inner_radius_, r2 = radius_ * radius_;
    if (phimax_ >= 2 * kPiD) {
        Point2f d = sample_uniform_disk_concentric(u);
        double rho2 = double(d.x) * d.x + double(d.y) * d.y;
        double rho = std::sqrt(ri2 + rho2 * (r2 - ri2)), k = rho2 > 0 ? rho / std::sqrt(rho2) : 0;
        return {d.x * k, d.y * k, height_};
    }
    double rho = std::sqrt(ri2 + u.x * (r2 - ri2)), phi = u.y * phimax_;
    return {rho * std::cos(phi), rho * std::sin(phi), height_};
}

double DiskShape::object_area() const {
    return phimax_ / 2 * (radius_ * radius_ - inner_radius_ * inner_radius_);
}

Bounds3f DiskShape::object_bounds() const {
    Bounds3f b;
    b.extend(Point3f(float(-radius_), float(-radius_), float(height_)));
    b.extend(Point3f(float(radius_), float(radius_), float(height_)));
    return b;
}

} // namespace illum
