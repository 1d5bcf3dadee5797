#include "illum/render/shadow_transmittance.h"

#include <algorithm>

#include "illum/bsdf/material.h"
#include "illum/medium/medium.h"
#include "illum/medium/sample_majorant.h"

namespace illum {

namespace {

// Roulette for ratio tracking once the estimate is small (PBR 4th ed. §14.2.2): kept with probability 1/4.
constexpr float kShadowRouletteBelow = 0.05f;
constexpr float kShadowKeep = 0.25f;
// Surfaces without material a shadow ray may cross before it is given up (a scene of nested interfaces
// needs far fewer; this only guards against a degenerate one).
constexpr int kMaxCrossings = 256;

// The media's transmittance along one stretch of a shadow ray, (0, tmax) of `ray` in ray.medium
// (nothing: vacuum), into t_ray, with the techniques' densities into r_u and r_l.
void attenuate(const Ray& ray, float tmax, int ch, PCG32& rng, const SampledWavelengths& lambda,
               HomogeneousCache* cache, SampledSpectrum& t_ray, SampledSpectrum* r_u, SampledSpectrum* r_l) {
    if (!ray.medium) return;
    if (ray.medium->is_homogeneous()) {
        // Exact: T = exp(-σ_t d); the unidirectional technique would have passed with density T.
        const MediumProperties mp =
            cache ? cache->get(*ray.medium, lambda) : ray.medium->sample_point(ray.o, lambda);
        float d = std::min(tmax, 3.0e38f / std::max(length(ray.d), 1e-30f)) * length(ray.d);
        SampledSpectrum t = exp(-(mp.sigma_a + mp.sigma_s) * d);
        t_ray *= t;
        *r_u *= t;
        return;
    }
    SampledSpectrum t_maj = sample_t_maj(
        ray, tmax, rng.uniform_float(), rng, lambda, ch, cache,
        [&](Point3f, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum t_m) {
            // Ratio tracking: each tentative collision weighs by σ_n / σ_maj (PBR 4th ed. §14.2.2).
            SampledSpectrum sigma_n = null_coefficient(mp, sigma_maj);
            float pdf = t_m[ch] * sigma_maj[ch];
            t_ray *= t_m * sigma_n / pdf;
            *r_l *= t_m * sigma_maj / pdf;
            *r_u *= t_m * sigma_n / pdf;
            SampledSpectrum estimate = t_ray / (*r_l + *r_u).average();
            if (estimate.max_component() < kShadowRouletteBelow) {
                if (rng.uniform_float() < 1 - kShadowKeep)
                    t_ray = SampledSpectrum(0.0f);
                else
                    t_ray /= kShadowKeep;
            }
            return !t_ray.is_black();
        });
    SampledSpectrum rel = relative_to_channel(t_maj, ch);
    t_ray *= rel;
    *r_l *= rel;
    *r_u *= rel;
}

// Crossing by crossing: one closest-hit ray from each surface passed to the next (the way for a ray that
// crosses more surfaces than Accelerator::shadow_crossings gathers).
SampledSpectrum crossing_by_crossing(const Scene& scene, Ray ray, const ShadowTarget& target, int ch,
                                     PCG32& rng, const SampledWavelengths& lambda, SampledSpectrum* r_u,
                                     SampledSpectrum* r_l, std::uint64_t* rays, HomogeneousCache* cache) {
    SampledSpectrum t_ray(1.0f);
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        SurfaceHit hit;
        ++*rays;
        bool found = scene.intersect(ray, &hit);
        if (found && hit.material && !hit.material->is_interface()) return SampledSpectrum(0.0f); // blocked
        attenuate(ray, found ? hit.t : ray.tmax, ch, rng, lambda, cache, t_ray, r_u, r_l);
        if (t_ray.is_black() || !t_ray.is_finite()) return SampledSpectrum(0.0f);
        if (!found) return t_ray;
        // Through the interface, on towards the light.
        if (target.at_infinity)
            ray = hit.spawn_ray(target.wi);
        else if (target.n == Normal3f{})
            ray = hit.spawn_ray_to(target.p);
        else {
            const Medium* m = hit.medium_for(target.p - hit.p);
            ray = spawn_ray_to(hit.p, hit.p_error, hit.n, target.p, target.p_error, target.n);
            ray.medium = m;
            ray.time = hit.time;
        }
    }
    return SampledSpectrum(0.0f);
}

} // namespace

SampledSpectrum shadow_transmittance(const Scene& scene, Ray ray, const ShadowTarget& target, int ch,
                                     PCG32& rng, const SampledWavelengths& lambda, SampledSpectrum* r_u,
                                     SampledSpectrum* r_l, std::uint64_t* rays, HomogeneousCache* cache) {
    ++*rays;
    // No context filter either.
    if (is_plain_occlusion(scene, ray))
        return scene.accelerator.occluded(ray) ? SampledSpectrum(0.0f) : SampledSpectrum(1.0f);
    // One traversal gathers the surfaces the ray passes; the stretches between them are in the media the
    // surfaces separate.
    Accelerator::ShadowCrossings xs;
    if (!scene.accelerator.shadow_crossings(ray, &xs)) {
        if (!xs.overflow) return SampledSpectrum(0.0f); // blocked
        return crossing_by_crossing(scene, ray, target, ch, rng, lambda, r_u, r_l, rays, cache);
    }
    SampledSpectrum t_ray(1.0f);
    Ray stretch = ray;
    float t0 = 0;
    for (int i = 0; i <= xs.n; ++i) {
        float t1 = i < xs.n ? xs.hits[i].t() : ray.tmax;
        stretch.o = ray(t0);
        attenuate(stretch, t1 - t0, ch, rng, lambda, cache, t_ray, r_u, r_l);
        if (t_ray.is_black() || !t_ray.is_finite()) return SampledSpectrum(0.0f);
        if (i == xs.n) break;
        // The medium beyond the surface, on the side the ray leaves it.
        if (!scene.accelerator.medium_beyond(xs.hits[i], ray, &stretch.medium)) continue;
        t0 = t1;
    }
    return t_ray;
}

} // namespace illum
