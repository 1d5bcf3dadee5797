// A moving transform as Embree's instance motion blur takes it: time steps spread evenly over the
// shutter interval (Embree's ray time 0..1), each a decomposition T R U with U upper triangular
// (RTCQuaternionDecomposition), between which Embree interpolates T and U linearly and R by slerp.
//
// pbrt-v4's AnimatedTransform interpolates T, R and the polar factor S (symmetric) in the same way, so
// two steps, at the shutter's open and close, reproduce it exactly when (a) its motion spans the whole
// shutter (TransformTimes start <= shutteropen and end >= shutterclose: a slerp restricted to a
// sub-interval is the slerp between its ends) and (b) S is diagonal at both ends (U = S; true of every
// transform written as translate, rotate, then a scale along the object's axes). Otherwise
// (the motion starts or stops inside the shutter, or S has off-diagonal terms: a scale applied after a
// rotation) the motion is sampled at kManySteps steps, each exact, with Embree's interpolation between
// them (off by O(1/steps²) of the motion in between, and by up to one step's motion where it starts or
// stops).
#pragma once

#include <vector>

#include "illum/math/animated_transform.h"

namespace illum {

inline constexpr int kManyMotionSteps = 65;

// The components T, R, U (U upper triangular: R U is the 3x3 part) at each step, at times
// open + (close - open) i / (n - 1); consecutive rotations on the shorter arc. A zero-length shutter gives
// one step, the transform at `open`.
std::vector<TransformComponents> motion_steps(const AnimatedTransform& motion, double open, double close);

// The nested motion outer(t) · inner(t): a moving shape inside an object definition placed by an object
// instance, still or moving (pbrt-v4 nests an AnimatedPrimitive in the instance's TransformedPrimitive or
// AnimatedPrimitive, carrying the ray through both at its time). Each step is the product at its time,
// decomposed. Two steps when Embree's interpolation between the shutter's ends reproduces the product
// (checked at interior times: so for an outer similarity, still, around a motion as above); else
// kManyMotionSteps.
std::vector<TransformComponents> motion_steps(const AnimatedTransform& outer, const AnimatedTransform& inner,
                                              double open, double close);

} // namespace illum
