#include "illum/texture/noise.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

// Perlin's permutation of 0..255 (Perlin 2002), indexed up to 511 by repeating it.
constexpr unsigned char kPermutation[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,
    69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,
    94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136,
    171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122,
    60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161,
    1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196, 135, 130, 116, 188, 159, 86,
    164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126,
    255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213,
    119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,   129, 22,  39,  253,
    19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,  242, 193,
    238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
    181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,
    222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180,
};

int perm(int i) { return kPermutation[i & 255]; }

// The gradient of lattice point (x, y, z) dotted with the offset (dx, dy, dz): one of the 12 edge
// directions of a cube (with four repeated, 16 in all) picked by the hashed corner (Perlin 2002).
float gradient(int x, int y, int z, float dx, float dy, float dz) {
    int h = perm(perm(perm(x) + y) + z) & 15;
    float u = h < 8 || h == 12 || h == 13 ? dx : dy;
    float v = h < 4 || h == 12 || h == 13 ? dy : dz;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

// 6t⁵ - 15t⁴ + 10t³: zero first and second derivatives at 0 and 1.
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }

float lerp(float t, float a, float b) { return (1 - t) * a + t * b; }

} // namespace

float perlin_noise(float x, float y, float z) {
    x = std::fmod(x, float(1 << 30));
    y = std::fmod(y, float(1 << 30));
    z = std::fmod(z, float(1 << 30));
    if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) return 0; // (int of NaN is undefined)
    const int ix = int(std::floor(x)), iy = int(std::floor(y)), iz = int(std::floor(z));
    const float dx = x - float(ix), dy = y - float(iy), dz = z - float(iz);
    const int x0 = ix & 255, y0 = iy & 255, z0 = iz & 255;
    // perm(a + b) with a, b < 256 reads the doubled table's 0..510: the same as (a + b) & 255 here.
    auto g = [&](int i, int j, int k) { return gradient(x0 + i, y0 + j, z0 + k, dx - i, dy - j, dz - k); };
    const float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    float x00 = lerp(wx, g(0, 0, 0), g(1, 0, 0)), x10 = lerp(wx, g(0, 1, 0), g(1, 1, 0));
    float x01 = lerp(wx, g(0, 0, 1), g(1, 0, 1)), x11 = lerp(wx, g(0, 1, 1), g(1, 1, 1));
    return lerp(wz, lerp(wy, x00, x10), lerp(wy, x01, x11));
}

namespace {

// The number of octaves the footprint resolves: n = clamp(-1 - log2 max(|∂p/∂x|, |∂p/∂y|), 0, max) (pbrt-v4's
// FBm; PBR 4th ed. §10.6.3: an octave of frequency 1.99^i has a period of about 2^-i, and is dropped once
// the footprint spans half of it). A zero footprint resolves all octaves.
float resolved_octaves(Vector3f dpdx, Vector3f dpdy, int max_octaves) {
    float len2 = std::max(length_squared(dpdx), length_squared(dpdy));
    if (!(len2 > 0)) return float(max_octaves);
    return std::clamp(-1 - 0.5f * std::log2(len2), 0.0f, float(max_octaves));
}

// The weight of the partly resolved octave: smoothstep over [0.3, 0.7] of its fraction (pbrt-v4's FBm).
float partial_weight(float fraction) {
    float t = std::clamp((fraction - 0.3f) / 0.4f, 0.0f, 1.0f);
    return t * t * (3 - 2 * t);
}

} // namespace

float fbm(Point3f p, Vector3f dpdx, Vector3f dpdy, float omega, int max_octaves) {
    float n = resolved_octaves(dpdx, dpdy, max_octaves);
    int whole = int(std::floor(n));
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < whole; ++i) {
        sum += amplitude * perlin_noise(scaled(p, frequency));
        frequency *= 1.99f;
        amplitude *= omega;
    }
    float w = partial_weight(n - float(whole));
    if (w > 0) sum += amplitude * w * perlin_noise(scaled(p, frequency));
    return sum;
}

float turbulence(Point3f p, Vector3f dpdx, Vector3f dpdy, float omega, int max_octaves) {
    float n = resolved_octaves(dpdx, dpdy, max_octaves);
    int whole = int(std::floor(n));
    float sum = 0, frequency = 1, amplitude = 1;
    for (int i = 0; i < whole; ++i) {
        sum += amplitude * std::abs(perlin_noise(scaled(p, frequency)));
        frequency *= 1.99f;
        amplitude *= omega;
    }
    // The partly resolved octave blends from |noise|'s mean allowance 0.2 to |noise|; each dropped octave
    // adds 0.2 of its amplitude (pbrt-v4's Turbulence, which starts those at the partial octave's amplitude).
    float w = partial_weight(n - float(whole));
    sum += amplitude * (w > 0 ? (1 - w) * 0.2f + w * std::abs(perlin_noise(scaled(p, frequency))) : 0.2f);
    for (int i = whole; i < max_octaves; ++i) {
        sum += amplitude * 0.2f;
        amplitude *= omega;
    }
    return sum;
}

} // namespace illum
