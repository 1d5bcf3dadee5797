// Shapes that can carry an area light: they are sampled for next-event estimation (by solid angle from
// a receiving point where the shape allows it, by area otherwise) and for photon emission (by area).
#pragma once

#include <cmath>
#include <optional>

#include "illum/math/bounds.h"
#include "illum/math/direction_cone.h"
#include "illum/math/vector.h"
#include "illum/radiometry/quantity.h"

namespace illum {

// The receiving point a shape is sampled from.
struct ShapeSampleContext {
    Point3f p;
    Vector3f p_error;
    Normal3f n; // zero for points not on a surface
    // Whether the caller reads the sample's uv; a shape may leave it zero otherwise (a sphere's costs an
    // atan2 and an acos).
    bool uv_needed = true;
};

// A point on a shape: what a sample is, before its density.
struct ShapePoint {
    Point3f p;
    Vector3f p_error;
    Normal3f n; // outward (emitting side) normal at p
    Point2f uv;
};

// A point sampled by area (sample_area()) and its density per square metre on the shape.
struct AreaShapeSample : ShapePoint {
    AreaPdf pdf;
};

// A point sampled as seen from a receiver (sample()): its density per steradian there, and the unit
// direction from the receiver to it, which every shape computes on the way (its caller, a light's
// sample_li(), would otherwise compute it again and wait for a second square root).
struct ShapeSample : ShapePoint {
    SolidAnglePdf pdf;
    Vector3f wi;
};

// The sample of the point pt seen from `receiver` with density pdf: none where the point is the receiver.
inline std::optional<ShapeSample> seen_from(Point3f receiver, const ShapePoint& pt, SolidAnglePdf pdf) {
    Vector3f d = pt.p - receiver;
    float d2 = length_squared(d);
    if (d2 == 0) return std::nullopt;
    return ShapeSample{pt, pdf, d / std::sqrt(d2)};
}

class AreaShape {
public:
    virtual ~AreaShape() = default;
    virtual float area() const = 0;
    virtual Bounds3f bounds() const = 0;
    // A point uniformly distributed by area; pdf per unit area.
    virtual AreaShapeSample sample_area(Point2f u) const = 0;
    // A point seen from ctx; pdf per unit solid angle at ctx.
    virtual std::optional<ShapeSample> sample(const ShapeSampleContext& ctx, Point2f u) const;
    // The solid-angle density with which sample() returns the point p_hit (normal n_hit) seen from ctx
    // along the unit direction wi.
    virtual SolidAnglePdf pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                              Normal3f n_hit) const;
    // The density per unit area with which sample_area() returns the shape's point p (1 / area for the
    // shapes that sample uniformly).
    virtual AreaPdf area_pdf(Point3f) const { return AreaPdf(1 / area()); }
    // A cone holding every normal of the surface (oriented as its hits' normals are); the whole sphere
    // unless a shape knows better.
    virtual DirectionCone normal_bounds() const { return DirectionCone::entire_sphere(); }

protected:
    // Converts an area sample to a solid-angle one as seen from ctx (pdf_ω = pdf_A r² / |cos θ_l|).
    static std::optional<ShapeSample> area_to_solid_angle(const ShapeSampleContext& ctx, AreaShapeSample s);
    static SolidAnglePdf area_pdf_to_solid_angle(AreaPdf pdf_area, Point3f p_ref, Point3f p_hit,
                                                 Normal3f n_hit, Vector3f wi);
};

} // namespace illum
