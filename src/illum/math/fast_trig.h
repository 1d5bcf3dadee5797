// Float arctangent and tangent by polynomials, for the hot paths that call them once per sample
// (equiangular sampling, medium/equiangular.h), where libm's atanf and tanf took ~8% of a fog render.
// Both keep the relative error below 4e-7 (3 ulp; libm: 1), checked against libm in tests/math.
//
// The coefficients are minimax-like fits (iteratively reweighted least squares on Chebyshev nodes, made
// for illum): atan(x)/x as a polynomial in x² on [0, 1], tan(x)/x as one in x² on [0, π/4]. Range
// reduction: atan(x) = π/2 - atan(1/x) for |x| > 1; tan(x) = 1 / tan(π/2 - x) for x > π/4, with π/2 split
// in two floats (Cody & Waite) so that π/2 - x keeps its digits near the pole.
#pragma once

#include <cmath>

namespace illum {

inline float fast_atan(float x) {
    const float a = std::abs(x);
    const bool big = a > 1;
    const float r = big ? 1 / a : a;
    const float z = r * r;
    float p = -0.004693262744694948f;
    p = p * z + 0.024252356961369514f;
    p = p * z - 0.059486329555511475f;
    p = p * z + 0.099142886698246f;
    p = p * z - 0.14019478857517242f;
    p = p * z + 0.19969724118709564f;
    p = p * z - 0.33331990242004395f;
    p = p * z + 0.9999998807907104f;
    float t = p * r;
    if (big) t = 1.57079637050628662f - t - (-4.37113882867379e-8f);
    return std::copysign(t, x);
}

// For |x| < π/2.
inline float fast_tan(float x) {
    const float a = std::abs(x);
    const bool big = a > 0.785398163397448f;
    // π/2 - a in two steps: 1.5707963705 (the float nearest π/2) and its error.
    const float r = big ? (1.57079637050628662f - a) + (-4.37113882867379e-8f) : a;
    const float z = r * r;
    float p = 0.00949830748140812f;
    p = p * z + 0.002895722398534417f;
    p = p * z + 0.02460089698433876f;
    p = p * z + 0.053349122405052185f;
    p = p * z + 0.1333989053964615f;
    p = p * z + 0.33333075046539307f;
    p = p * z + 1.0f;
    float t = p * r;
    if (big) t = 1 / t;
    return std::copysign(t, x);
}

} // namespace illum
