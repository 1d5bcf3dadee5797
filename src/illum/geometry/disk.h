// pbrt's disk: in object space the annulus inner_radius <= r <= radius at z = height, normal +z; placed
// in the world by an affine transform. Sampled by area.
#pragma once

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"
#include "illum/math/transform.h"

namespace illum {

class DiskShape final : public AreaShape {
public:
    DiskShape(const Transform& world_from_object, float height, float radius, float inner_radius,
              bool flip_normal);

    float area() const override { return area_; }
    Bounds3f bounds() const override;
    ShapeSample sample_area(Point2f u) const override;

    // Ray-disk intersection; returns the hit distance or nothing.
    std::optional<float> intersect(const Ray& ray) const;
    void fill_hit(float t, const Ray& ray, SurfaceHit* hit) const;

private:
    Transform world_from_object_, object_from_world_;
    float height_, radius_, inner_radius_;
    bool flip_;
    float area_;
    Normal3f normal_; // world space, emitting side
};

} // namespace illum
