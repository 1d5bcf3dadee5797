// pbrt's analytic shapes (sphere, disk, cylinder): a surface defined in object space and placed in the
// world by any affine transform. Rays are intersected in object space in double precision (the ray is
// carried there by the inverse transform), so a non-uniform scale is exact; hits are reprojected onto the
// surface and carried back with a conservative error bound (PBR 4th ed. §6.8).
//
// Area and sampling: each shape samples its object-space surface uniformly by area. An affine map M
// scales the area element at a point of unit object normal n by J = |det M| |M^-T n| (the normal's
// cofactor rule), a constant s² for a similarity (rotation, uniform scale s, translation), so there the
// world samples stay uniform; under a non-uniform scale they are not, and the world pdf 1 / (A_obj J) is
// evaluated point by point (sample_area() and pdf() agree). The world area is s² A_obj, or the integral
// A_obj E[J] computed once by quadrature.
#pragma once

#include <cmath>

#include "illum/geometry/shape.h"
#include "illum/geometry/surface_hit.h"
#include "illum/math/transform.h"

namespace illum {

class FloatTexture;

// A point or vector in double precision: object-space intersection arithmetic only.
struct Vec3d {
    double x = 0, y = 0, z = 0;
    Vec3d operator+(Vec3d o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3d operator-(Vec3d o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3d operator*(double s) const { return {x * s, y * s, z * s}; }
};
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(Vec3d a) { return std::sqrt(dot(a, a)); }
// The azimuth φ in [0, 2π) of (x, y).
inline double azimuth(double x, double y) {
    double phi = std::atan2(y, x);
    return phi < 0 ? phi + 2 * kPiD : phi;
}

// The real roots of a t² + 2 b t + c = 0 in increasing order, from q = -(b + sign(b) √disc) (no
// cancellation between b and the root, Numerical Recipes §5.6); disc = b² - a c is given by the caller,
// who can compute it without cancellation. Returns how many (0 or 2).
inline int solve_quadratic(double a, double b, double c, double disc, double t[2]) {
    if (disc < 0 || a == 0) return 0;
    double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    t[0] = std::min(t0, t1);
    t[1] = std::max(t0, t1);
    return 2;
}

// A candidate crossing of a ray with the surface: ray parameter, object-space point, and which root of
// the shape's equation it is (0 near, 1 far: the alpha test draws an independent number for each).
struct Crossing {
    double t = 0;
    Vec3d p; // the object-space point, for the alpha test (zero where the roots come from world_roots)
    int root = 0;
};

class AnalyticShape : public AreaShape, public ShadingPartialsSource {
public:
    AnalyticShape(const Transform& world_from_object, bool flip_normal);

    // Crossings of the world-space ray with the (clipped) surface in (tmin, tmax), nearest first; returns
    // how many (at most 2).
    int crossings(const Ray& ray, float tmin, float tmax, Crossing out[2]) const;
    // Fills a hit at ray parameter t (the point is reprojected onto the surface).
    void fill_hit(float t, const Ray& ray, SurfaceHit* hit) const;
    // pbrt-v4's partials at the object-space point `local` (∂n/∂u, ∂n/∂v carried to the world as normals).
    ShadingPartials shading_partials(std::uint32_t prim, Point3f local) const override;
    // Whether a ray leaving the surface at ray parameter t along ray.d goes to the side the hit's normal
    // (fill_hit's n, orientation included) points to: the sign of d · n, taken in object space, where
    // d_obj · n_obj = d · (M^-T n_obj) needs no normal carried to the world (shadow rays through media).
    bool leaves_along_normal(float t, const Ray& ray) const {
        Vec3d d = to_object(ray.d);
        Vec3d p = to_object(ray.o) + d * double(t);
        double s = dot(d, outward_at(p));
        return flip_ ? s < 0 : s > 0;
    }
    // The point, normal and uv of a crossing: what an alpha texture is evaluated at.
    SurfaceHit alpha_point(const Crossing& c) const;

    // pbrt-v4's "alpha": a cut-out texture, evaluated at the hit's uv (nullptr: opaque).
    void set_alpha(const FloatTexture* alpha) { alpha_ = alpha; }
    const FloatTexture* alpha() const { return alpha_; }

    float area() const override { return area_; }
    Bounds3f bounds() const override;
    AreaShapeSample sample_area(Point2f u) const override;
    SolidAnglePdf pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                      Normal3f n_hit) const override;
    // The density per unit world area with which sample_area() returns the world point p.
    AreaPdf area_pdf(Point3f p) const override;

    const Transform& world_from_object() const { return world_from_object_; }
    // Whether world_from_object is a similarity (then `scale()` is its uniform scale factor).
    bool is_similarity() const { return similarity_; }
    double scale() const { return scale_; }
    bool flip_normal() const { return flip_; }

protected:
    // A point of the object-space surface with what a hit needs there.
    struct SurfacePoint {
        Vec3d p;    // on the surface
        Vec3d n;    // outward (pbrt's ∂p/∂u × ∂p/∂v direction), unit length
        Vec3d dpdu; // ∂p/∂u
        Point2f uv; // pbrt's parameterisation
    };
    // Call at the end of the derived constructor: computes the world area and the culling bounds.
    void init_area();
    // The world point, error bound, normal and uv of the surface point nearest to object point p.
    ShapePoint world_sample(Vec3d p) const;

    // Roots of the object-space ray o + t d with the unclipped surface (increasing), and whether a point
    // on it lies within the clipped part.
    virtual int roots(Vec3d o, Vec3d d, double t[2]) const = 0;
    virtual bool inside_clip(Vec3d p) const = 0;
    // The roots of the world-space ray with the surface where a shape can find them without the object
    // space (a whole round sphere without alpha: nothing to clip, no object point needed), else -1.
    virtual int world_roots(const Ray&, double[2]) const { return -1; }
    // The surface point nearest to the (almost on-surface) object point p.
    virtual SurfacePoint surface_at(Vec3d p) const = 0;
    // The outward normal, of any length, at the surface point nearest p (surface_at's n unnormalised).
    virtual Vec3d outward_at(Vec3d p) const { return surface_at(p).n; }
    // ∂p/∂v, ∂n/∂u and ∂n/∂v of the outward unit normal at a surface point (pbrt-v4's values: what the
    // Weingarten equations give), for bump mapping only.
    struct SecondPartials {
        Vec3d dpdv, dndu, dndv;
    };
    virtual SecondPartials partials_at(const SurfacePoint& sp) const = 0;
    // A point uniformly distributed by object-space area, and that area.
    virtual Vec3d sample_object(Point2f u) const = 0;
    virtual double object_area() const = 0;
    virtual Bounds3f object_bounds() const = 0;

    Vec3d to_object(Point3f p) const;
    Vec3d to_object(Vector3f v) const;
    // World point of an object point, with its error bound.
    Point3f to_world(Vec3d p, Vector3f* p_error) const;
    Vector3f to_world(Vec3d v) const;
    Normal3f world_normal(Vec3d n_obj) const; // normalised, flipped as the orientation says
    // A normal's derivative (∂n/∂u) carried as pbrt-v4 carries it: by M^-T, neither normalised nor flipped.
    Normal3f world_normal_derivative(
        Vec3d dn_obj) const; // The area scale J = |det M| |M^-T n| at unit object normal n.
    double area_scale(Vec3d n) const;

private:
    Transform world_from_object_;
    bool flip_;
    bool similarity_ = false;
    double scale_ = 1, det_ = 1;
    float area_ = 0;
    const FloatTexture* alpha_ = nullptr;
    // World bounds, widened against rounding, that crossings() tests before its double-precision roots.
    Bounds3f cull_;
    bool cull_valid_ = false;
    bool misses_bounds(const Ray& ray, float tmin, float tmax) const;
};

} // namespace illum
