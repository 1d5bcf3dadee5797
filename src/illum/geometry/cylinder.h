// pbrt's cylinder: in object space x² + y² = r², zmin <= z <= zmax, 0 <= φ <= φmax, open at both ends
// (PBR 4th ed. §6.3), placed in the world by any affine transform. uv = (φ / φmax, (z - zmin) /
// (zmax - zmin)); the normal points away from the axis. Sampled by area.
#pragma once

#include "illum/geometry/analytic_shape.h"

namespace illum {

class CylinderShape final : public AnalyticShape {
public:
    // phimax in radians, in (0, 2π]; zmin and zmax in either order.
    CylinderShape(const Transform& world_from_object, float radius, float zmin, float zmax, float phimax,
                  bool flip_normal);

protected:
    int roots(Vec3d o, Vec3d d, double t[2]) const override;
    bool inside_clip(Vec3d p) const override;
    SurfacePoint surface_at(Vec3d p) const override;
    SecondPartials partials_at(const SurfacePoint& s) const override;
    Vec3d sample_object(Point2f u) const override;
    double object_area() const override;
    Bounds3f object_bounds() const override;

private:
    double radius_, zmin_, zmax_, phimax_;
};

} // namespace illum
