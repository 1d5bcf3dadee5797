// Light tracing (pbrt-v4's "lightpath"; Veach 1997 §10.2 with t = 1, PBR 4th ed. §16.3): particles leave
// the lights and, at every vertex, connect to the camera through its importance (camera_importance.h);
// each connection is splatted onto the film where it lands. In participating media particles scatter at
// real collisions (delta tracking, sample_majorant.h) and connect from there too; connections pass
// interfaces and carry the media's transmittance (shadow_transmittance.h). Media's own emission is not
// traced (volpath collects it). It renders caustics seen directly that a
// path tracer finds only by chance, and cannot see specular surfaces (their vertices never connect).
//
// Budget: one particle per pixel sample, so spp means what it means to pbrt-v4 (spp × pixels particles).
//
// Determinism: particle (pixel, sample) draws its numbers from the pixel sampler of that pixel and sample
// index. Particles are grouped in chunks of kChunkPixels pixels at one sample index; a wave of
// kWaveChunks chunks is traced in parallel, each chunk collecting its splats in its own list, and the
// lists are then added to the film in chunk order (by one task, while the next wave is traced). The image
// is therefore the same at any thread count.
#pragma once

#include <vector>

#include "illum/camera/splat_film.h"
#include "illum/render/renderer.h"
#include "illum/util/line_aligned.h"

namespace illum {

class LightPathIntegrator final : public WholeImageIntegrator {
public:
    // max_depth: the most scattering vertices a particle connects from (pbrt-v4's "maxdepth"; -1
    // unbounded, Russian roulette ends it). Throws illum::Error if the camera has no importance.
    // caustics_only: only paths whose first scattering after the light is specular (a delta lobe) and whose
    // camera connection is from a non-specular vertex: the caustics that volpath leaves to light tracing
    // (volpath_integrator.h), and the direct view of area lights weighed against volpath's camera rays
    // (direct_view_mis.h); no particles from environment lights.
    LightPathIntegrator(const Scene& scene, int max_depth, bool caustics_only = false);
    RenderResult render_image(const RenderOptions& options) const override;

private:
    // Traces one particle with tc's sampler already at its pixel sample; appends its splats to `out`.
    // Returns the number of non-finite or negative contributions dropped.
    int trace_particle(ThreadContext& tc, bool spectral, LineAlignedVector<Splat>& out) const;

    int max_depth_;
    bool caustics_only_;
};

} // namespace illum
