#include "illum/geometry/cylinder.h"

#include <algorithm>

namespace illum {

CylinderShape::CylinderShape(const Transform& world_from_object, float radius, float zmin, float zmax,
                             float phimax, bool flip_normal)
    : AnalyticShape(world_from_object, flip_normal), radius_(radius), zmin_(std::min(zmin, zmax)),
      zmax_(std::max(zmin, zmax)), phimax_(std::clamp(double(phimax), 0.0, 2 * kPiD)) {
    init_area();
}

// (o_x + t d_x)² + (o_y + t d_y)² = r²: a t² + 2 b t + c = 0 over the xy components. The discriminant
// b² - a c = a r² - (o_x d_y - o_y d_x)² (Lagrange's identity) does not cancel for distant origins.
int CylinderShape::roots(Vec3d o, Vec3d d, double t[2]) const {
    double a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y,
           c = o.x * o.x + o.y * o.y - radius_ * radius_;
    double cr = o.x * d.y - o.y * d.x;
    return solve_quadratic(a, b, c, a * radius_ * radius_ - cr * cr, t);
}

bool CylinderShape::inside_clip(Vec3d p) const {
    if (p.z < zmin_ || p.z > zmax_) return false;
    return phimax_ >= 2 * kPiD || azimuth(p.x, p.y) <= phimax_;
}

AnalyticShape::SurfacePoint CylinderShape::surface_at(Vec3d p) const {
    double rho = std::sqrt(p.x * p.x + p.y * p.y);
    SurfacePoint s;
    s.n = rho > 0 ? Vec3d{p.x / rho, p.y / rho, 0} : Vec3d{1, 0, 0};
    s.p = {s.n.x * radius_, s.n.y * radius_, std::clamp(p.z, zmin_, zmax_)};
    s.uv = {float(azimuth(s.p.x, s.p.y) / phimax_), float((s.p.z - zmin_) / (zmax_ - zmin_))};
    s.dpdu = Vec3d{-s.p.y, s.p.x, 0} * phimax_;
    return s;
}

// ∂p/∂v along the axis; n = (x, y, 0) / r, so ∂n/∂u = ∂p/∂u / r and ∂n/∂v = 0 (pbrt-v4's Weingarten
// result).
AnalyticShape::SecondPartials CylinderShape::partials_at(const SurfacePoint& s) const {
    return {Vec3d{0, 0, zmax_ - zmin_}, s.dpdu * (1 / radius_), {}};
}

// z uniform in [zmin, zmax], φ uniform in [0, φmax]: the area element r dφ dz is constant; the area is
// φmax r (zmax - zmin) (PBR 4th ed. §6.3.3).
Vec3d CylinderShape::sample_object(Point2f u) const {
    double z = zmin_ + u.x * (zmax_ - zmin_), phi = u.y * phimax_;
    return {radius_ * std::cos(phi), radius_ * std::sin(phi), z};
}

double CylinderShape::object_area() const { return phimax_ * radius_ * (zmax_ - zmin_); }

Bounds3f CylinderShape::object_bounds() const {
    Bounds3f b;
    b.extend(Point3f(float(-radius_), float(-radius_), float(zmin_)));
    b.extend(Point3f(float(radius_), float(radius_), float(zmax_)));
    return b;
}

} // namespace illum
