// pbrt-v4's "cloud" medium (CloudMedium; pbrt-v4 media.h): a procedural density in medium space,
//   d(p) = clamp(clamp(4.5 density (1 - p.y) Σ_{i<5} 0.5^{i+1} N(1.99^i q), 0, 1) + 2 max(0, 1/2 - p.y), 0,
//   1),
// with q = frequency · p perturbed by two octaves of the noise's gradient when wispiness > 0
// (q += 0.05 wispiness 0.5^i ∇N(10 · 1.99^i q), the gradient by forward differences of step 0.01, as
// pbrt-v4's DNoise), N being Perlin's gradient noise as pbrt-v4 defines it (util/noise.cpp: Perlin's
// permutation, pbrt's choice of gradients, the quintic fade 6t^5 - 15t^4 + 10t^3). σ_a and σ_s are the
// density times the coefficients; there is no emission. The density is at most 1, so the majorant is σ_t
// over the part of the ray inside the box [p0, p1].
#pragma once

#include "illum/medium/medium.h"
#include "illum/medium/medium_box.h"
#include "illum/medium/medium_spectrum.h"
#include "illum/texture/noise.h"

namespace illum {

// pbrt-v4's DNoise(p): the gradient of Noise (perlin_noise, texture/noise.h) by forward differences.
Vector3f perlin_noise_gradient(Point3f p);

struct CloudParams {
    MediumBox box;
    MediumSpectrum sigma_a, sigma_s;
    float g = 0;
    float density = 1, wispiness = 1, frequency = 5;
};

class CloudMedium final : public Medium {
public:
    explicit CloudMedium(CloudParams p) : p_(std::move(p)) {}

    bool is_emissive() const override { return false; }
    MediumProperties sample_point(Point3f p, const SampledWavelengths& lambda) const override;
    MajorantIterator sample_ray(const Ray& ray, float tmax, const SampledWavelengths& lambda) const override;
    // The density at a medium-space point.
    float density(Point3f p) const;

private:
    CloudParams p_;
};

} // namespace illum
