// Perlin noise and its sums, as pbrt-v4 defines them for its procedural textures (PBR 4th ed. §10.6):
// gradient noise on the integer lattice with Perlin's "improved" gradients and quintic fade (K. Perlin,
// "Improving Noise", SIGGRAPH 2002), fractional Brownian motion and turbulence (sums of octaves at
// frequencies 1.99^i and amplitudes ω^i).
//
// pbrt-v4 chooses the number of octaves from the ray differentials' footprint (n = clamp(-1 - log2 |dp|,
// 0, max)); illum carries no ray differentials yet, so a zero footprint is passed, which pbrt-v4 treats as
// "all octaves", and that is what these sums compute.
#pragma once

#include "illum/math/vector.h"

namespace illum {

// p scaled about the origin (texture space is where these textures live).
inline Point3f scaled(Point3f p, float s) { return {p.x * s, p.y * s, p.z * s}; }

// Noise in [-1, 1] (zero at lattice points). Coordinates are taken modulo 2^30, as pbrt-v4 does.
float perlin_noise(float x, float y = 0.5f, float z = 0.5f);
inline float perlin_noise(Point3f p) { return perlin_noise(p.x, p.y, p.z); }

// Σ_{i < octaves} ω^i noise(1.99^i p).
float fbm(Point3f p, float omega, int octaves);
// Σ_{i < octaves} ω^i |noise(1.99^i p)| + 0.2 ω^octaves (pbrt-v4's allowance for the octaves it leaves out,
// which with a zero footprint is the last term's).
float turbulence(Point3f p, float omega, int octaves);

} // namespace illum
