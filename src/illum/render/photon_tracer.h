// Photons: particles of light power emitted by the scene's lights and traced through it with the BSDFs in
// importance transport (TransportMode::Importance), as in stochastic progressive photon mapping (Hachisuka
// & Jensen 2009; PBR 3rd ed. §16.2, 4th ed. online "SPPM"). Photon i of an iteration draws its numbers from
// one Sobol stream indexed by the photon's global number iteration · N + i (pbrt-v4 uses a scrambled Halton
// sequence the same way), so a photon's path depends only on (seed, iteration, i), never on the thread
// that traces it.
//
// A photon starts with the power estimate β = Φ_sample / p_light, where the light is picked by power
// (p_light its probability) and Φ_sample = L |cos θ| / (p_pos p_dir) is LightLeSample::flux; over N photons
// E[Σ β] / N = Σ_lights Φ, so each photon carries the power β / N. At each scattering event
// β ← β f |cos θ_i| / p, then Russian roulette continues it with probability min(1, max β_new / max β),
// pbrt-v4's rule, which keeps a photon's power roughly constant.
#pragma once

#include <cstdint>

#include "illum/geometry/surface_hit.h"
#include "illum/radiometry/sampled_wavelengths.h"
#include "illum/render/sampler.h"
#include "illum/render/scene.h"
#include "illum/util/arena.h"

namespace illum {

// A photon as it leaves its light.
struct EmittedPhoton {
    Ray ray;
    SampledSpectrum beta; // power estimate Φ_sample / p_light [W]
};

// A photon arriving at a surface.
struct PhotonArrival {
    const SurfaceHit& hit;
    Vector3f wi;          // unit direction back towards where the photon came from
    SampledSpectrum beta; // its power estimate [W] (divide by the photon count for the photon's share)
    int bounce;           // 0: straight from the light; n: after n scattering events
    const SampledWavelengths& lambda; // its wavelengths (a dispersive event may have terminated some)
};

class PhotonTracer {
public:
    // max_depth: surface hits per photon (pbrt-v4's SPPM "maxdepth": a photon is traced through at most
    // max_depth intersections). The photon streams' seed is the sampler's (start_photon_sample).
    PhotonTracer(const Scene& scene, int max_depth) : scene_(scene), max_depth_(max_depth) {}

    // Starts the sampler at photon `global_index` and emits it; false when the light emits nothing there.
    bool emit(std::uint64_t global_index, const SampledWavelengths& lambda, Sampler& sampler,
              EmittedPhoton* out) const;

    // Traces photon `global_index`, calling visit(const PhotonArrival&) at every surface it reaches, in
    // order. lambda is the photon's copy of the wavelengths (dispersion may terminate its secondaries);
    // arena holds one BSDF at a time and is reset at each vertex. Returns the rays traced.
    template <class Visit>
    std::uint64_t trace(std::uint64_t global_index, SampledWavelengths lambda, Sampler& sampler,
                        ScratchArena& arena, Visit&& visit) const;

private:
    const Scene& scene_;
    int max_depth_;
};

// The Sobol sampler of photon streams: one "pixel" far outside any image, the photon's global number as
// the sample index (the high bits pick another pixel beyond 2^32 photons).
inline void start_photon_sample(Sampler& sampler, std::uint64_t global_index) {
    sampler.start_pixel_sample({-1 - int(global_index >> 32), -7}, int(std::uint32_t(global_index)));
}

template <class Visit>
std::uint64_t PhotonTracer::trace(std::uint64_t global_index, SampledWavelengths lambda, Sampler& sampler,
                                  ScratchArena& arena, Visit&& visit) const {
    EmittedPhoton ph;
    if (!emit(global_index, lambda, sampler, &ph)) return 0;
    Ray ray = ph.ray;
    SampledSpectrum beta = ph.beta;
    std::uint64_t rays = 0;
    for (int depth = 0; depth < max_depth_; ++depth) {
        SurfaceHit hit;
        ++rays;
        if (!scene_.intersect(ray, &hit)) break;
        visit(PhotonArrival{hit, -ray.d, beta, depth, lambda});
        arena.reset();
        BSDF bsdf = surface_bsdf(hit, lambda, arena);
        if (!bsdf) {
            // A pure interface: the photon passes; the hit does not count against the depth.
            ray = hit.spawn_ray(ray.d);
            --depth;
            continue;
        }
        if (bsdf.flags() == kNone) break;
        const float u_lobe =
            sampler.get_1d_if(bsdf.reads_lobe_sample()); // before u_dir (a call's arguments have no order)
        const Point2f u_dir = sampler.get_2d();
        auto bs = bsdf.sample(-ray.d, u_lobe, u_dir, TransportMode::Importance);
        if (!bs) break;
        SampledSpectrum beta_new = beta * throughput_weight(bs->f, abs_dot(bs->wi, hit.ns), bs->pdf);
        // Russian roulette: continue with probability min(1, max β_new / max β), reweighted by it.
        float q = std::max(0.0f, 1 - beta_new.max_component() / beta.max_component());
        if (sampler.get_1d() < q) break;
        beta = beta_new / (1 - q);
        if (!beta.is_finite() || beta.is_black()) break;
        ray = hit.spawn_ray(bs->wi);
    }
    arena.reset();
    return rays;
}

} // namespace illum
