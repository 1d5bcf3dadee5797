// The box [p0, p1] a bounded medium (the grids, the cloud) fills in its own space, and the maps from world
// space into it: medium space is the CTM at MakeNamedMedium (pbrt-v4: renderFromMedium), and the grids'
// "unit" space maps the box to [0, 1]^3 (pbrt-v4's Bounds3::Offset), where their samples and majorant
// grids live. A ray keeps its parameter t through both maps (o and d are transformed, d is not
// renormalised), so the segments the DDA returns are in the caller's t.
#pragma once

#include <algorithm>

#include "illum/geometry/ray.h"
#include "illum/math/bounds.h"
#include "illum/math/transform.h"

namespace illum {

class MediumBox {
public:
    MediumBox() = default;
    // bounds must be non-empty with p0 < p1 on every axis (the factories check it).
    MediumBox(const Transform& world_from_medium, Bounds3f bounds)
        : bounds_(bounds), medium_from_world_(world_from_medium.inverse()) {
        Vector3f d = bounds.diagonal();
        unit_from_world_ = Transform::scale(1 / d.x, 1 / d.y, 1 / d.z) *
                           Transform::translate(Vector3f(-bounds.lo.x, -bounds.lo.y, -bounds.lo.z)) *
                           medium_from_world_;
    }

    const Bounds3f& bounds() const { return bounds_; }
    Point3f medium_point(Point3f world) const { return medium_from_world_(world); }
    Point3f unit_point(Point3f world) const { return unit_from_world_(world); }

    // The part of o + t d (world), t in [0, tmax), inside the box, as the ray in unit space (*o, *d) and
    // its t range [*t0, *t1]; false when the ray misses the box. A slab test (Kay & Kajiya 1986) with
    // pbrt-v4's widening of the far distance by 1 + 2 γ_3 against rounding (Bounds3::IntersectP).
    bool clip(const Ray& ray, float tmax, Point3f* o, Vector3f* d, float* t0, float* t1) const {
        *o = unit_from_world_(ray.o);
        *d = unit_from_world_(ray.d);
        float lo = 0, hi = tmax;
        for (int a = 0; a < 3; ++a) {
            float oa = (*o)[a], da = (*d)[a];
            if (da == 0) {
                if (!(oa >= 0 && oa <= 1)) return false; // parallel to the slab and outside it (or NaN)
                continue;
            }
            float inv = 1 / da;
            float tn = (0 - oa) * inv, tf = (1 - oa) * inv;
            if (tn > tf) std::swap(tn, tf);
            tf *= 1 + 2 * gamma_bound(3);
            lo = tn > lo ? tn : lo;
            hi = tf < hi ? tf : hi;
            if (!(lo <= hi)) return false;
        }
        *t0 = lo;
        *t1 = hi;
        return lo < hi;
    }

private:
    Bounds3f bounds_;
    Transform medium_from_world_, unit_from_world_;
};

} // namespace illum
