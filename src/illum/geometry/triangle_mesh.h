// Triangle meshes in world space, and single triangles as area-light shapes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"
#include "illum/math/transform.h"

namespace illum {

struct TriangleMesh final : ShadingPartialsSource {
    std::vector<Point3f> p;             // world space
    std::vector<Normal3f> n;            // per vertex, world space; empty when the mesh gives none
    std::vector<Point2f> uv;            // per vertex; empty when none
    std::vector<std::uint32_t> indices; // three per triangle
    std::vector<int> face_indices;      // per triangle, pbrt-v4's "faceIndices" (Ptex); empty: all 0
    // pbrt-v4: the geometric normal is normalize(cross(p0 - p2, p1 - p2)), turned to the side of the
    // shading normals when the mesh has them, else flipped by ReverseOrientation xor a transform that
    // swaps handedness.
    bool flip_normal = false;

    std::size_t triangle_count() const { return indices.size() / 3; }
    std::array<Point3f, 3> vertices(std::size_t tri) const {
        return {p[indices[3 * tri]], p[indices[3 * tri + 1]], p[indices[3 * tri + 2]]};
    }
    float triangle_area(std::size_t tri) const;
    int face_index(std::size_t tri) const { return face_indices.empty() ? 0 : face_indices[tri]; }
    // Transforms object-space data to world space in place.
    void transform(const Transform& world_from_object);
    // Computes the face normals and the hit records; call once the data is in world space (and change it
    // no more).
    void finalize();
    bool finalized() const {
        return hit_triangles_.size() == triangle_count() && hit_vertices_.size() == p.size();
    }
    // Fills a hit from Embree's barycentrics (b1, b2) on triangle tri (p = b0 p0 + b1 p1 + b2 p2).
    void fill_hit(std::uint32_t tri, float b1, float b2, float t, const Ray& ray, SurfaceHit* hit) const;
    // pbrt-v4's Triangle shading partials at barycentrics (local.x, local.y) = (b1, b2) of triangle tri.
    ShadingPartials shading_partials(std::uint32_t tri, Point3f local) const override;
    // The geometric normal of triangle tri, oriented by the mesh's rules.
    Normal3f geometric_normal(std::size_t tri) const { return hit_triangles_[tri].n; }

private:
    // What fill_hit reads, interleaved: a hit loads one record of the triangle and one per vertex instead
    // of a cache line in each of five arrays (indices, p, n, uv, face normals). The water caustic's
    // 100k-triangle water mesh spent most of fill_hit waiting for those loads.
    struct HitTriangle {
        std::uint32_t v[3];
        Normal3f n; // unit geometric normal, the orientation rules applied
        int face_index;
    };
    struct HitVertex {
        Point3f p;
        Normal3f n; // zero when the mesh has no normals
        Point2f uv; // zero when it has no uv
    };
    std::vector<HitTriangle> hit_triangles_;
    std::vector<HitVertex> hit_vertices_;
};

// One triangle of a mesh as an emitter's shape. Sampled by solid angle as a spherical triangle (Arvo
// 1995) when it subtends a moderate solid angle, by area otherwise (too small: the spherical map loses
// precision and buys nothing over area sampling; too large: the cosine at the receiver is far from
// uniform).
class TriangleShape final : public AreaShape {
public:
    // The mesh must be in world space already (its vertices do not change afterwards).
    TriangleShape(const TriangleMesh* mesh, std::uint32_t index);

    float area() const override { return area_; }
    Bounds3f bounds() const override;
    DirectionCone normal_bounds() const override {
        return DirectionCone(Vector3f(mesh_->geometric_normal(index_)));
    }
    AreaShapeSample sample_area(Point2f u) const override;
    std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const override;
    SolidAnglePdf pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                      Normal3f n_hit) const override;

    // Below 0.05 sr area sampling is more efficient: on the Cornell box, whose light subtends 0.02-0.1 sr
    // from most of the box, MSE x time is 0.0085 with this threshold, 0.0085 with area sampling only and
    // 0.0102 with spherical sampling from 3e-4 sr up (docs/performance.md). Above it the spherical
    // sampler's lower variance is worth its cost (about twice that of an area sample).
    static constexpr float kMinSphericalSolidAngle = 0.05f;
    static constexpr float kMaxSphericalSolidAngle = 6.22f;

private:
    bool use_spherical_sampling(Point3f p) const;
    ShapePoint at_barycentrics(float b0, float b1, float b2) const;
    const TriangleMesh* mesh_;
    std::uint32_t index_;
    // The triangle's corners and their uv (pbrt-v4's (0,0), (1,0), (1,1) without any), kept here: a light
    // sample reads them at every call, and through the mesh's index and vertex arrays that was two loads
    // in a row for each.
    std::array<Point3f, 3> v_;
    std::array<Point2f, 3> uv_{Point2f{0, 0}, Point2f{1, 0}, Point2f{1, 1}};
    float area_;
    Point3f centroid_;
    Vector3f area_normal_; // (p1 - p0) × (p2 - p0): twice the area along the normal
};

} // namespace illum
