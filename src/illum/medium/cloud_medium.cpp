#include "illum/medium/cloud_medium.h"

#include <algorithm>
#include <cmath>

namespace illum {

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
