// Float arctangent, tangent, sine and cosine by polynomials, for the hot paths that call them once per
// sample: equiangular sampling (medium/equiangular.h), where libm's atanf and tanf took ~8% of a fog
// render, and the angles of the sampling warps (math/warp.cpp, the GGX visible normals), where sincosf took
// ~3% of a path-traced frame. atan and tan keep the relative error below 4e-7 (3 ulp; libm: 1), sine and
// cosine the absolute error below 1.5e-7; checked against libm in tests/math.
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

// sin a and cos a for |a| <= π/4 by their Taylor series, through a⁹ and a¹⁰ (the next terms are below
// 2e-9 and 1.2e-10 there).
inline void fast_sincos_quarter(float a, float* s, float* c) {
    const float z = a * a;
    float ps = 2.7557319e-6f;    // 1/9!
    ps = ps * z - 1.9841270e-4f; // 1/7!
    ps = ps * z + 8.3333333e-3f; // 1/5!
    ps = ps * z - 1.6666667e-1f; // 1/3!
    *s = a + a * z * ps;
    float pc = -2.7557319e-7f;   // 1/10!
    pc = pc * z + 2.4801587e-5f; // 1/8!
    pc = pc * z - 1.3888889e-3f; // 1/6!
    pc = pc * z + 4.1666667e-2f; // 1/4!
    pc = pc * z - 0.5f;
    *c = 1 + z * pc;
}

// sin 2πu and cos 2πu for u in [0, 1] (a sampled azimuth): u = k/4 + r with |r| <= 1/8 (exact: Sterbenz),
// then the quarter turns k rotate (cos, sin) of 2πr.
inline void fast_sincos_2pi(float u, float* s, float* c) {
    const int k = int(4 * u + 0.5f); // the nearest quarter (u >= 0)
    const float r = u - 0.25f * float(k);
    float sr, cr;
    fast_sincos_quarter(6.28318530717958648f * r, &sr, &cr);
    switch (k & 3) {
    case 0:
        *s = sr, *c = cr;
        break;
    case 1:
        *s = cr, *c = -sr;
        break;
    case 2:
        *s = -sr, *c = -cr;
        break;
    default:
        *s = -cr, *c = sr;
        break;
    }
}

} // namespace illum
