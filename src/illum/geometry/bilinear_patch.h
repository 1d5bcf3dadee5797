// pbrt-v4's bilinear patches ("bilinearmesh"): each patch of corners p00, p10, p01, p11 is the surface
//   p(u, v) = lerp(u, lerp(v, p00, p01), lerp(v, p10, p11)),  (u, v) in [0, 1]²,
// intersected exactly by Reshetov's ray/patch test ("Cool Patches: A Geometric Approach to Ray/Bilinear
// Patch Intersections", Ray Tracing Gems, 2019; PBR 4th ed. §6.6): u solves the quadratic for the distance
// from the ray to the u-isolines, v and t follow from the closest approach of the ray to the isoline at u.
//
// As pbrt-v4's BilinearPatch: the texture coordinates are the bilinear interpolation of the vertices' "uv"
// (else (u, v)), ∂p/∂u and ∂p/∂v follow that parameterisation, the geometric normal is ∂p/∂u × ∂p/∂v
// (flipped by ReverseOrientation xor a handedness swap, or turned to the side of the shading normal, which
// is the bilinear interpolation of "N"), ∂n/∂u and ∂n/∂v come from the Weingarten equations (the patch's
// only second derivative is ∂²p/∂u∂v = p00 - p01 - p10 + p11).
//
// Sampling (BilinearPatchShape): a rectangle is sampled uniformly in area, or by the solid angle it subtends
// (spherical rectangle, Ureña et al. 2013) warped by the bilinear interpolation of the receiver's cosine
// towards its corners when that solid angle exceeds 1e-4 sr; any other patch by (u, v) drawn in proportion
// to the bilinear interpolation of |∂p/∂u × ∂p/∂v| at its corners, whose density per unit area is
// bilinear_pdf(u, v) / |∂p/∂u × ∂p/∂v| (approximately uniform, exactly normalised). A mesh with pbrt-v4's
// "emissionfilename" samples every patch's (u, v) by that image instead (piecewise constant in the pixels'
// channel average, v = 0 at the image's bottom row, to match an area light's image looked up at (u, 1 - v)):
// density image_pdf(u, v) / |∂p/∂u × ∂p/∂v|.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"
#include "illum/math/bounds.h"
#include "illum/math/distribution.h"
#include "illum/math/transform.h"

namespace illum {

// A ray's crossing of a patch: its parameters (u, v) and the ray parameter t.
struct PatchCrossing {
    float u = 0, v = 0, t = 0;
};

// The nearest crossing of the ray o + t d with the patch in (0, tmax) (pbrt-v4's IntersectBilinearPatch:
// crossings closer than a rounding bound on t are rejected).
std::optional<PatchCrossing> intersect_bilinear_patch(Point3f o, Vector3f d, float tmax, Point3f p00,
                                                      Point3f p10, Point3f p01, Point3f p11);

struct BilinearPatchMesh final : ShadingPartialsSource {
    std::vector<Point3f> p;              // world space
    std::vector<Normal3f> n;             // per vertex, world space; empty when the mesh gives none
    std::vector<Point2f> uv;             // per vertex; empty when none
    std::vector<std::uint32_t> indices;  // four per patch: p00, p10, p01, p11
    std::vector<int> face_indices;       // per patch, pbrt-v4's "faceIndices" (Ptex); empty: all 0
    bool flip_normal = false;            // ReverseOrientation xor a handedness-swapping transform
    std::vector<std::uint8_t> rectangle; // per patch, pbrt-v4's IsRectangle; filled by finalize()
    // pbrt-v4's "emissionfilename": the density over (u, v) every patch of the mesh samples its emitting
    // points by (null: none).
    std::shared_ptr<const Distribution2D> emission_distribution;

    std::size_t patch_count() const { return indices.size() / 4; }
    int face_index(std::size_t patch) const { return face_indices.empty() ? 0 : face_indices[patch]; }
    // p00, p10, p01, p11
    std::array<Point3f, 4> corners(std::size_t patch) const {
        const std::uint32_t* v = &indices[4 * patch];
        return {p[v[0]], p[v[1]], p[v[2]], p[v[3]]};
    }
    // The bounds of the patch: those of its corners, whose convex hull holds it.
    Bounds3f patch_bounds(std::size_t patch) const;
    // Transforms object-space data to world space in place (normals by the inverse transpose, negated
    // under ReverseOrientation as pbrt-v4 does).
    void transform(const Transform& world_from_object, bool reverse_orientation);
    // Decides which patches are rectangles; call once the data is in world space.
    void finalize();

    // The texture coordinates (s, t) at (u, v): the bilinear interpolation of the vertices' uv, else (u, v).
    Point2f texture_uv(std::size_t patch, float u, float v) const;
    // The unit geometric normal at (u, v), oriented as the mesh says.
    Normal3f geometric_normal(std::size_t patch, float u, float v) const;
    // The interpolated shading normal at (u, v) (zero when the mesh has no normals).
    Normal3f shading_normal(std::size_t patch, float u, float v) const;
    // Fills a hit at patch parameters (u, v), ray parameter t.
    void fill_hit(std::uint32_t patch, float u, float v, float t, const Ray& ray, SurfaceHit* hit) const;
    // pbrt-v4's partials at patch parameters (local.x, local.y) = (u, v).
    ShadingPartials shading_partials(std::uint32_t patch, Point3f local) const override;
    // The error bound of a point of the patch: γ6 (|p00| + |p10| + |p01| + |p11|).
    Vector3f point_error(std::size_t patch) const;
};

// One patch of a mesh as an emitter's shape.
class BilinearPatchShape final : public AreaShape {
public:
    // The mesh must be in world space and finalized (its vertices do not change afterwards).
    BilinearPatchShape(const BilinearPatchMesh* mesh, std::uint32_t index);

    // The exact area ∫∫ |∂p/∂u × ∂p/∂v| du dv (a rectangle's in closed form, any other patch's by 8 x 8
    // Gauss-Legendre quadrature, far below float rounding for the smooth integrand).
    float area() const override { return area_; }
    Bounds3f bounds() const override { return mesh_->patch_bounds(index_); }
    AreaShapeSample sample_area(Point2f u) const override;
    std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const override;
    SolidAnglePdf pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                      Normal3f n_hit) const override;
    // A rectangle is planar: its one normal. Any other patch: the whole sphere.
    DirectionCone normal_bounds() const override {
        if (!is_rectangle()) return DirectionCone::entire_sphere();
        return DirectionCone(Vector3f(mesh_->geometric_normal(index_, 0.5f, 0.5f)));
    }
    // The density per unit area with which sample_area() returns the patch's point p.
    AreaPdf area_pdf(Point3f p) const override;

    // pbrt-v4's threshold: below this solid angle a rectangle is sampled by area.
    static constexpr float kMinSphericalSolidAngle = 1e-4f;

    // The patch parameters (u, v) of a point of the patch (Newton's iteration on the closest point).
    Point2f patch_uv(Point3f p) const;

private:
    bool is_rectangle() const { return mesh_->rectangle[index_] != 0; }
    // Whether the patch is sampled by the solid angle it subtends (a rectangle without an emission image).
    bool samples_solid_angle() const { return is_rectangle() && !mesh_->emission_distribution; }
    // The density per unit area of sample_area() at patch parameters (u, v).
    float area_density(Point2f uv) const;
    ShapePoint point_at(Point2f uv) const;
    const BilinearPatchMesh* mesh_;
    std::uint32_t index_;
    float area_ = 0;
};

} // namespace illum
