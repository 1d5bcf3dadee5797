// A cone of directions about a unit axis w, of half-angle θ (stored as cos θ): the normals an emitter's
// surface can have, or the directions a box subtends from a point. cos θ = -1 is the whole sphere; an
// empty cone has no direction (cos θ = +inf). PBR 4th ed. §3.8.4 defines the same bounds.
#pragma once

#include <limits>

#include "illum/math/bounds.h"

namespace illum {

struct DirectionCone {
    Vector3f w{0, 0, 1};
    float cos_theta = std::numeric_limits<float>::infinity();

    DirectionCone() = default; // empty
    DirectionCone(Vector3f axis, float cos_theta_) : w(normalize(axis)), cos_theta(cos_theta_) {}
    explicit DirectionCone(Vector3f direction) : DirectionCone(direction, 1.0f) {}
    static DirectionCone entire_sphere() { return DirectionCone(Vector3f(0, 0, 1), -1.0f); }

    bool empty() const { return cos_theta == std::numeric_limits<float>::infinity(); }
    bool contains(Vector3f v) const { return !empty() && dot(w, normalize(v)) >= cos_theta; }
};

// The smallest cone about a direction between the axes that holds both cones (Conty Estevez & Kulla 2018,
// Alg. 1): with θa ≥ θb the half-angles and θd the angle between the axes, a already holds b when
// θd + θb ≤ θa; otherwise the union has half-angle θo = (θa + θd + θb) / 2, its axis a's turned by θo - θa
// towards b's (the whole sphere once θo ≥ π).
DirectionCone union_of(const DirectionCone& a, const DirectionCone& b);

// The directions from p towards the box b: the cone about the box's bounding sphere, whose half-angle has
// sin² θ = r² / d² (the whole sphere when p lies inside the sphere).
DirectionCone directions_towards(const Bounds3f& b, Point3f p);

} // namespace illum
