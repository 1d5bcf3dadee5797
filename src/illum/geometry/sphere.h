// A sphere in world space (center, radius). Emitting spheres are sampled uniformly inside the cone
// they subtend from the receiver (PBR 4th ed. §6.2.4); from inside, uniformly by area.
#pragma once

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"

namespace illum {

class SphereShape final : public AreaShape {
public:
    SphereShape(Point3f center, float radius, bool flip_normal)
        : center_(center), radius_(radius), flip_(flip_normal) {}

    Point3f center() const { return center_; }
    float radius() const { return radius_; }

    float area() const override { return 4 * kPi * radius_ * radius_; }
    Bounds3f bounds() const override;
    ShapeSample sample_area(Point2f u) const override;
    std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const override;
    float pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit, Normal3f n_hit) const override;

    // Fills a hit at ray parameter t (the point is reprojected onto the surface).
    void fill_hit(float t, const Ray& ray, SurfaceHit* hit) const;

private:
    // Puts p on the surface exactly and bounds its error (γ_5 |p - c|).
    void reproject(Point3f* p, Vector3f* err) const;
    Normal3f outward(Point3f p) const;
    Point2f uv_at(Point3f p) const;

    Point3f center_;
    float radius_;
    bool flip_;
};

} // namespace illum
