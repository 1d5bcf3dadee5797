#include "illum/medium/cloud_medium.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace illum {

namespace {

// Ken Perlin's permutation of 0..255 ("Improving Noise", SIGGRAPH 2002), the table pbrt-v4 uses.
constexpr std::uint8_t kPerm[256] = {
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
    222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

// pbrt-v4 indexes a table of two copies; wrapping the index is the same.
int perm(int i) { return kPerm[i & 255]; }

// The gradient of lattice point (x, y, z) dotted with the offset (dx, dy, dz): one of twelve edge
// directions of the cube (four of them twice), chosen by the hashed lattice point.
float grad(int x, int y, int z, float dx, float dy, float dz) {
    int h = perm(perm(perm(x) + y) + z) & 15;
    float u = (h < 8 || h == 12 || h == 13) ? dx : dy;
    float v = (h < 4 || h == 12 || h == 13) ? dy : dz;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
float mix(float t, float a, float b) { return (1 - t) * a + t * b; }

} // namespace

float perlin_noise(Point3f p) {
    // Reduced modulo 2^30 first so that the lattice coordinates fit an int (pbrt-v4 does the same).
    float x = std::fmod(p.x, float(1 << 30)), y = std::fmod(p.y, float(1 << 30)),
          z = std::fmod(p.z, float(1 << 30));
    if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) return 0;
    float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    float dx = x - fx, dy = y - fy, dz = z - fz;
    int ix = int(fx) & 255, iy = int(fy) & 255, iz = int(fz) & 255;
    float w000 = grad(ix, iy, iz, dx, dy, dz), w100 = grad(ix + 1, iy, iz, dx - 1, dy, dz);
    float w010 = grad(ix, iy + 1, iz, dx, dy - 1, dz), w110 = grad(ix + 1, iy + 1, iz, dx - 1, dy - 1, dz);
    float w001 = grad(ix, iy, iz + 1, dx, dy, dz - 1), w101 = grad(ix + 1, iy, iz + 1, dx - 1, dy, dz - 1);
    float w011 = grad(ix, iy + 1, iz + 1, dx, dy - 1, dz - 1);
    float w111 = grad(ix + 1, iy + 1, iz + 1, dx - 1, dy - 1, dz - 1);
    float wx = fade(dx), wy = fade(dy), wz = fade(dz);
    float y0 = mix(wy, mix(wx, w000, w100), mix(wx, w010, w110));
    float y1 = mix(wy, mix(wx, w001, w101), mix(wx, w011, w111));
    return mix(wz, y0, y1);
}

Vector3f perlin_noise_gradient(Point3f p) {
    const float h = 0.01f;
    float n = perlin_noise(p);
    return Vector3f(perlin_noise(p + Vector3f(h, 0, 0)) - n, perlin_noise(p + Vector3f(0, h, 0)) - n,
                    perlin_noise(p + Vector3f(0, 0, h)) - n) /
           h;
}

float CloudMedium::density(Point3f p) const {
    Point3f q = Point3f(p.x * p_.frequency, p.y * p_.frequency, p.z * p_.frequency);
    if (p_.wispiness > 0) {
        float amplitude = 0.05f * p_.wispiness, freq = 10;
        for (int i = 0; i < 2; ++i) {
            q = q + perlin_noise_gradient(Point3f(q.x * freq, q.y * freq, q.z * freq)) * amplitude;
            amplitude *= 0.5f;
            freq *= 1.99f;
        }
    }
    float d = 0, amplitude = 0.5f, freq = 1;
    for (int i = 0; i < 5; ++i) {
        d += amplitude * perlin_noise(Point3f(q.x * freq, q.y * freq, q.z * freq));
        amplitude *= 0.5f;
        freq *= 1.99f;
    }
    d = std::clamp((1 - p.y) * 4.5f * p_.density * d, 0.0f, 1.0f);
    d += 2 * std::max(0.0f, 0.5f - p.y);
    return std::clamp(d, 0.0f, 1.0f);
}

MediumProperties CloudMedium::sample_point(Point3f p, const SampledWavelengths& lambda) const {
    float d = density(p_.box.medium_point(p));
    return {p_.sigma_a.at(lambda) * d, p_.sigma_s.at(lambda) * d, HenyeyGreenstein{p_.g},
            SampledSpectrum(0.0f)};
}

MajorantIterator CloudMedium::sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const {
    Point3f o;
    Vector3f d;
    float t0, t1;
    if (!p_.box.clip(ray, tmax, &o, &d, &t0, &t1)) return {};
    return MajorantIterator::single(t0, t1, p_.sigma_a.at(lambda) + p_.sigma_s.at(lambda));
}

} // namespace illum
