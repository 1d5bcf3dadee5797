// What a light sampler may know of an emitter without sampling it: where it is, which way it can emit and
// how strongly (Conty Estevez & Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree
// Splitting"; PBR 4th ed. §12.6.3). The emitter lies in `bounds`; every normal of its surface lies within
// θo of the axis w, and it emits only within θe beyond a normal (π/2 for a Lambertian surface: the
// hemisphere; a spot light's falloff for a spot). phi is its typical strength: 4π times the radiant
// intensity it sends towards a point within its cone (4π I for a point or spot light; for a Lambertian
// emitter of radiance L and area A, whose intensity L A cos θ averages L A / 2 over the hemisphere, 2π L A).
#pragma once

#include "illum/math/direction_cone.h"

namespace illum {

struct LightBounds {
    Bounds3f bounds;
    Vector3f w{0, 0, 1};
    float phi = 0;
    float cos_theta_o = 1;
    float cos_theta_e = 0;
    bool two_sided = false;

    // The importance of the emitters inside for a receiver at p with normal n (zero: not on a surface),
    // an upper estimate of their contribution there (Conty Estevez & Kulla 2018, §4.3):
    //   phi · cos θ' / d² · cos θ'_i,
    // with d the distance to the box's centre (no less than an eighth of the box's diagonal), θ' the angle
    // from the normal cone to the direction towards p, narrowed by the angle θb the box subtends from p,
    //   θ' = max(0, θw - θo - θb),
    // zero once θ' ≥ θe (nothing inside emits towards p), and θ'_i = max(0, θi - θb) with θi the angle
    // between n and the direction to the centre (taken on either side: transmission receives from below).
    // Never zero where an emitter inside can reach p, so sampling by it is unbiased.
    float importance(Point3f p, Normal3f n) const;
};

// LightBounds with what importance() derives from them computed once (the box's centre and bounding
// radius², sin θo): a light BVH evaluates it twice per level of every walk.
struct PreparedLightBounds {
    Point3f centre;
    float r2 = 0;
    Vector3f w{0, 0, 1};
    float phi = 0, cos_theta_o = 1, sin_theta_o = 0, cos_theta_e = 0;
    bool two_sided = false;

    PreparedLightBounds() = default;
    explicit PreparedLightBounds(const LightBounds& b);
    float importance(Point3f p, Normal3f n) const; // LightBounds::importance
};

// importance() of a and of b at one receiver, the two in the lanes of one SSE register where the processor
// has them: the light BVH asks for both children of every node it passes, and the two chains of square
// roots and divisions then run side by side. The values are importance()'s bit for bit (the same
// operations in the same order, lane by lane).
void importance_pair(const PreparedLightBounds& a, const PreparedLightBounds& b, Point3f p, Normal3f n,
                     float* importance_a, float* importance_b);

// A point emitter of strength phi sending light every way (θo = π, θe = π/2).
LightBounds point_bounds(Point3f p, float phi);

// The bounds of two groups of emitters together: the boxes' union, the normal cones' union (the narrower
// of the two emission spreads), the strengths' sum.
LightBounds union_of(const LightBounds& a, const LightBounds& b);

} // namespace illum
