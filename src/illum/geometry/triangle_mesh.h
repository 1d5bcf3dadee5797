// Triangle meshes in world space, and single triangles as area-light shapes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"
#include "illum/math/transform.h"

namespace illum {

struct TriangleMesh {
    std::vector<Point3f> p;  // world space
    std::vector<Normal3f> n; // per vertex, world space; empty when the mesh gives none
    std::vector<Point2f> uv; // per vertex; empty when none
    std::vector<std::uint32_t> indices; // three per triangle
    // pbrt-v4: the geometric normal is normalize(cross(p0 - p2, p1 - p2)), turned to the side of the
    // shading normals when the mesh has them, else flipped by ReverseOrientation xor a transform that
    // swaps handedness.
    bool flip_normal = false;

    std::size_t triangle_count() const { return indices.size() / 3; }
    std::array<Point3f, 3> vertices(std::size_t tri) const {
        return {p[indices[3 * tri]], p[indices[3 * tri + 1]], p[indices[3 * tri + 2]]};
    }
    float triangle_area(std::size_t tri) const;
    // Transforms object-space data to world space in place.
    void transform(const Transform& world_from_object);
    // Fills a hit from Embree's barycentrics (b1, b2) on triangle tri (p = b0 p0 + b1 p1 + b2 p2).
    void fill_hit(std::uint32_t tri, float b1, float b2, float t, const Ray& ray, SurfaceHit* hit) const;
    // The geometric normal of triangle tri with the mesh's orientation rules and shading normal (if any)
    // at the given barycentrics.
    Normal3f geometric_normal(std::size_t tri, float b0, float b1, float b2) const;
};

// One triangle of a mesh as an emitter's shape. Sampled by solid angle as a spherical triangle (Arvo
// 1995) when it subtends a moderate solid angle, by area otherwise (too small: the spherical map loses
// precision; too large: the cosine at the receiver is far from uniform).
class TriangleShape final : public AreaShape {
public:
    TriangleShape(const TriangleMesh* mesh, std::uint32_t index) : mesh_(mesh), index_(index) {}

    float area() const override { return mesh_->triangle_area(index_); }
    Bounds3f bounds() const override;
    ShapeSample sample_area(Point2f u) const override;
    std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const override;
    float pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit, Normal3f n_hit) const override;

    static constexpr float kMinSphericalSolidAngle = 3e-4f;
    static constexpr float kMaxSphericalSolidAngle = 6.22f;

private:
    float solid_angle(Point3f p) const;
    ShapeSample at_barycentrics(float b0, float b1, float b2) const;
    const TriangleMesh* mesh_;
    std::uint32_t index_;
};

} // namespace illum
