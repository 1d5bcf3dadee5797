// Perlin noise and its sums, as pbrt-v4 defines them for its procedural textures (PBR 4th ed. §10.6):
// gradient noise on the integer lattice with Perlin's "improved" gradients and quintic fade (K. Perlin,
// "Improving Noise", SIGGRAPH 2002), fractional Brownian motion and turbulence (sums of octaves at
// frequencies 1.99^i and amplitudes ω^i).
//
// As in pbrt-v4, the sums leave out the octaves finer than the hit's footprint (∂p/∂x, ∂p/∂y in the
// texture's space): n = clamp(-1 - log2 max |∂p|, 0, max octaves); a zero footprint sums them all.
#pragma once

#include "illum/math/vector.h"

namespace illum {

// p scaled about the origin (texture space is where these textures live).
inline Point3f scaled(Point3f p, float s) { return {p.x * s, p.y * s, p.z * s}; }

// Noise in [-1, 1] (zero at lattice points). Coordinates are taken modulo 2^30, as pbrt-v4 does; a
// non-finite point gives 0.
float perlin_noise(float x, float y = 0.5f, float z = 0.5f);
inline float perlin_noise(Point3f p) { return perlin_noise(p.x, p.y, p.z); }

// Σ_{i < ⌊n⌋} ω^i noise(1.99^i p), plus the octave ⌊n⌋ weighted by smoothstep(0.3, 0.7) of n's fraction.
float fbm(Point3f p, Vector3f dpdx, Vector3f dpdy, float omega, int max_octaves);
// Σ_{i < ⌊n⌋} ω^i |noise(1.99^i p)|, the octave ⌊n⌋ blended from 0.2 to its |noise| by the same weight, and
// 0.2 of the amplitude of each octave left out (pbrt-v4's allowance for |noise|'s mean).
float turbulence(Point3f p, Vector3f dpdx, Vector3f dpdy, float omega, int max_octaves);
// Every octave (a zero footprint).
inline float fbm(Point3f p, float omega, int octaves) { return fbm(p, {}, {}, omega, octaves); }
inline float turbulence(Point3f p, float omega, int octaves) { return turbulence(p, {}, {}, omega, octaves); }

} // namespace illum
