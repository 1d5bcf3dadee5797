// pbrt's sphere: in object space the sphere of radius r about the origin, clipped to zmin <= z <= zmax
// and to the azimuth 0 <= φ <= φmax (PBR 4th ed. §6.2), placed in the world by any affine transform.
// uv = (φ / φmax, (θ - θ(zmin)) / (θ(zmax) - θ(zmin))), θ = acos(z / r); the normal points outwards.
// A full sphere under a similarity transform without a cut-out is sampled uniformly inside the cone it
// subtends from a receiver outside it (§6.2.4); every other case by area.
#pragma once

#include "illum/geometry/analytic_shape.h"

namespace illum {

class SphereShape final : public AnalyticShape {
public:
    // phimax in radians, in (0, 2π]; zmin < zmax are clamped to [-r, r].
    SphereShape(const Transform& world_from_object, float radius, float zmin, float zmax, float phimax,
                bool flip_normal);
    // A whole sphere in world space.
    SphereShape(Point3f center, float radius, bool flip_normal);

    // Whether the sphere is whole (no z or φ clipping).
    bool is_full() const { return full_; }
    // Whether it is a whole round sphere in the world (a similarity transform) without a cut-out: then
    // it can be cone sampled, and Embree's native sphere could stand for it.
    bool is_round() const { return full_ && is_similarity() && !alpha(); }
    // World-space centre and radius (meaningful under a similarity transform).
    Point3f center() const { return center_; }
    float world_radius() const { return world_radius_; }

    std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const override;
    SolidAnglePdf pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                      Normal3f n_hit) const override;

protected:
    int roots(Vec3d o, Vec3d d, double t[2]) const override;
    int world_roots(const Ray& ray, double t[2]) const override;
    bool inside_clip(Vec3d p) const override;
    SurfacePoint surface_at(Vec3d p) const override;
    Vec3d outward_at(Vec3d p) const override { return p; } // surface_at's n = p / |p|
    SecondPartials partials_at(const SurfacePoint& s) const override;
    Vec3d sample_object(Point2f u) const override;
    double object_area() const override;
    Bounds3f object_bounds() const override;

private:
    // Whether sample() draws from the subtended cone for a receiver at p (else by area).
    bool cone_sampling(Point3f p) const;
    // The world point in the outward direction n_world from the centre (a unit vector up to rounding),
    // without its uv (left zero).
    ShapePoint world_point(Vector3f n_world) const;

    double radius_, zmin_, zmax_, theta_zmin_, theta_zmax_, phimax_;
    bool full_;
    // The world centre (the object origin carried by the transform) and scale × radius, kept: next-event
    // estimation asks for both at every light sample.
    Point3f center_;
    Vector3f center_error_;
    float world_radius_;
    // The same in double, for world_roots: the transform's image of the origin and scale × radius.
    Vec3d center_d_;
    double world_radius_d_;
};

} // namespace illum
