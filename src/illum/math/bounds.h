// Axis-aligned bounding boxes.
#pragma once

#include <limits>

#include "illum/math/vector.h"

namespace illum {

struct Bounds3f {
    Point3f lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
               std::numeric_limits<float>::infinity()};
    Point3f hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
               -std::numeric_limits<float>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(Point3f p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void extend(const Bounds3f& b) {
        if (b.empty()) return;
        extend(b.lo);
        extend(b.hi);
    }
    Vector3f diagonal() const { return hi - lo; }
    Point3f center() const { return lerp(0.5f, lo, hi); }
    // The sphere that encloses the box.
    void bounding_sphere(Point3f* c, float* r) const {
        *c = center();
        *r = empty() ? 0.0f : distance(*c, hi);
    }
};

} // namespace illum
