// The tiled parallel render loop on oneTBB. Pixels are split into tiles; each pixel is rendered by one
// task with its own deterministic sampler state (seed, pixel, sample index), so the image does not
// depend on the thread count or the order tiles run in.
#pragma once

#include <cstdint>
#include <string>

#include "illum/image/image.h"
#include "illum/render/integrator.h"
#include "illum/render/scene.h"

namespace illum {

struct RenderOptions {
    int spp = 16;
    double time_budget = 0; // seconds; > 0 renders whole passes of 1 spp until the budget is spent
    int threads = 0;        // 0: all hardware threads
    std::uint64_t seed = 0;
    std::string sampler = "sobol";
    bool quiet = false;
    int tile_size = 16;
    // Spectral mode: four sampled wavelengths per camera sample instead of RGB.
    bool spectral = false;
};

struct RenderResult {
    Image image;
    double seconds = 0;
    int spp = 0; // samples per pixel actually taken
    std::uint64_t samples = 0;
    std::uint64_t rays = 0;
    std::uint64_t nonfinite_samples =
        0; // NaN/Inf (or negative radiance) estimates: dropped, counted, never written
    int threads = 0;
};

// An integrator that renders the whole image itself rather than one camera sample at a time (light
// tracing splats particles onto the film, photon mapping runs iterations): render() hands over to it.
class WholeImageIntegrator : public Integrator {
public:
    using Integrator::Integrator;
    virtual RenderResult render_image(const RenderOptions& options) const = 0;
    // Not a per-camera-sample estimator.
    Radiance3 estimate(const Ray&, ThreadContext&) const override { return {}; }
};

// What every render loop derives from the options: the worker threads (0 asks for all the hardware's) and
// the sampler kind (an unknown name throws illum::Error naming the choices).
int render_threads(const RenderOptions& options);
SamplerKind render_sampler_kind(const RenderOptions& options);

RenderResult render(const Scene& scene, const Integrator& integrator, const RenderOptions& options);

} // namespace illum
