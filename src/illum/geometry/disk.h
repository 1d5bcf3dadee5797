// pbrt's disk: in object space the annulus inner_radius <= ρ <= radius at z = height, over the azimuth
// 0 <= φ <= φmax, normal +z (PBR 4th ed. §6.5); placed in the world by any affine transform.
// uv = (φ / φmax, (radius - ρ) / (radius - inner_radius)). Sampled by area.
#pragma once

#include "illum/geometry/analytic_shape.h"

namespace illum {

class DiskShape final : public AnalyticShape {
public:
    // phimax in radians, in (0, 2π].
    DiskShape(const Transform& world_from_object, float height, float radius, float inner_radius,
              bool flip_normal, float phimax = 2 * kPi);

    // Planar: every normal is the one a sampled point has.
    DirectionCone normal_bounds() const override {
        return DirectionCone(Vector3f(sample_area(Point2f{0.5f, 0.5f}).n));
    }

protected:
    int roots(Vec3d o, Vec3d d, double t[2]) const override;
    bool inside_clip(Vec3d p) const override;
    SurfacePoint surface_at(Vec3d p) const override;
    SecondPartials partials_at(const SurfacePoint& s) const override;
    Vec3d sample_object(Point2f u) const override;
    double object_area() const override;
    Bounds3f object_bounds() const override;

private:
    double height_, radius_, inner_radius_, phimax_;
};

} // namespace illum
