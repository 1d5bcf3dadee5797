// Delta tracking's free-flight sampling against a ray's majorant (PBR 4th ed., §14.1, "SampleT_maj"):
// along each majorant segment, tentative collisions are drawn with density σ_maj[c] exp(-σ_maj[c] t) for
// one channel c (the path's sampling channel); at each, `callback(p, mp, σ_maj, T_maj)` sees the medium's
// properties, σ_maj and the majorant transmittance T_maj = exp(-σ_maj Δt) since the previous collision
// (all channels), and returns whether to go on. The return value is T_maj from the last collision to
// tmax, or 1 when the callback stopped the walk. `u` gives the first step; `rng` the others.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>

#include "illum/math/rng.h"
#include "illum/medium/medium.h"

namespace illum {

// What happens at a tentative collision, chosen in the sampling channel with probabilities σ_a/σ_maj,
// σ_s/σ_maj and the rest (null). A homogeneous medium has no null collisions (σ_maj = σ_t), so rounding must
// not make one there.
enum class MediumEvent { Absorb, Scatter, Null };
inline MediumEvent choose_medium_event(const MediumProperties& mp, const SampledSpectrum& sigma_maj,
                                       int channel, float u, bool homogeneous) {
    float p_absorb = mp.sigma_a[channel] / sigma_maj[channel];
    if (u < p_absorb) return MediumEvent::Absorb;
    if (homogeneous || u < p_absorb + mp.sigma_s[channel] / sigma_maj[channel]) return MediumEvent::Scatter;
    return MediumEvent::Null;
}
// The null-collision coefficient σ_n = σ_maj - σ_a - σ_s (clamped at 0 against rounding).
inline SampledSpectrum null_coefficient(const MediumProperties& mp, const SampledSpectrum& sigma_maj) {
    return clamp(sigma_maj - mp.sigma_a - mp.sigma_s, 0.0f, std::numeric_limits<float>::infinity());
}

// `cache` (optional) holds a homogeneous medium's properties for the path.
template <class Callback>
SampledSpectrum sample_t_maj(Ray ray, float tmax, float u, PCG32& rng, const SampledWavelengths& lambda,
                             int channel, HomogeneousCache* cache, Callback&& callback) {
    // Work in a unit-length parameter so that σ_maj Δt is optical depth.
    float len = length(ray.d);
    tmax *= len;
    ray.d = ray.d / len;
    // A homogeneous medium's properties are the same at every collision: evaluated once, its σ_t the
    // majorant of the one segment (0, tmax), walked without a majorant iterator.
    const bool homogeneous = ray.medium->is_homogeneous();
    MediumProperties uniform;
    if (homogeneous)
        uniform = cache ? cache->get(*ray.medium, lambda) : ray.medium->sample_point(ray.o, lambda);
    SampledSpectrum t_maj(1.0f);
    // One majorant segment (t0, t1): false if the walk ended in it (t_maj is then the result).
    auto walk = [&](float t0, float t1, const SampledSpectrum& sigma_maj) {
        t1 = std::min(t1, FLT_MAX);
        // An infinite density (a degenerate input) is opaque: nothing passes, and no step could be taken.
        if (!std::isfinite(sigma_maj[channel])) {
            t_maj = SampledSpectrum(0.0f);
            return false;
        }
        if (sigma_maj[channel] == 0) {
            // No collisions in this channel: the segment only attenuates the others.
            t_maj *= exp(-sigma_maj * (t1 - t0));
            return true;
        }
        float t = t0;
        for (;;) {
            // -ln(1 - u): u is a float in [0, 1), so 1 - u loses at most 2^-25 (nothing for u >= 1/2), and
            // logf is several times cheaper than log1pf.
            float step = -std::log(1 - u) / sigma_maj[channel];
            u = rng.uniform_float();
            if (t + step >= t1) {
                t_maj *= exp(-sigma_maj * (t1 - t));
                return true;
            }
            t += step;
            t_maj *= exp(-sigma_maj * step);
            Point3f p = ray(t);
            if (!callback(p, homogeneous ? uniform : ray.medium->sample_point(p, lambda), sigma_maj, t_maj)) {
                t_maj = SampledSpectrum(1.0f);
                return false;
            }
            t_maj = SampledSpectrum(1.0f);
        }
    };
    if (homogeneous) {
        if (0 < tmax) walk(0, tmax, uniform.sigma_a + uniform.sigma_s); // (an empty segment: T_maj = 1)
        return t_maj;
    }
    MajorantIterator it = ray.medium->sample_ray(ray, tmax, lambda);
    while (std::optional<MajorantSegment> seg = it.next())
        if (!walk(seg->t0, seg->t1, seg->sigma_maj)) break;
    return t_maj;
}

template <class Callback>
SampledSpectrum sample_t_maj(Ray ray, float tmax, float u, PCG32& rng, const SampledWavelengths& lambda,
                             int channel, Callback&& callback) {
    return sample_t_maj(ray, tmax, u, rng, lambda, channel, nullptr, std::forward<Callback>(callback));
}

} // namespace illum
