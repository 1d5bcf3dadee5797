// The tiled parallel render loop on oneTBB. Pixels are split into tiles; each pixel is rendered by one
// task with its own deterministic sampler state (seed, pixel, sample index), so the image does not
// depend on the thread count or the order tiles run in.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "illum/image/image.h"
#include "illum/render/adaptive_sampling.h"
#include "illum/render/integrator.h"
#include "illum/render/render_group.h"
#include "illum/render/render_preview.h"
#include "illum/render/scene.h"
#include "illum/util/error.h"
#include "illum/util/progress.h"

namespace illum {

struct RenderOptions {
    int spp = 16;
    double time_budget = 0; // seconds; > 0 renders whole passes of 1 spp until the budget is spent
    int threads = 0;        // 0: all hardware threads
    std::uint64_t seed = 0;
    std::string sampler = "sobol";
    SamplerSettings sampler_settings; // the scene's Sampler parameters; the resolution is the scene's
    bool quiet = false;
    int tile_size = 16;
    // Spectral mode: four sampled wavelengths per camera sample instead of RGB.
    bool spectral = false;
    // Several processes rendering one image (render_group.h); null: this process renders every sample.
    RenderGroup* group = nullptr;
    // A live preview (render_preview.h): passes of one sample per pixel, each handed over when done.
    RenderPreview* preview = nullptr;
    // The camera rays of neighbouring samples traced as one Embree packet where the scene and integrator
    // allow it (renderer.cpp); the image is the same either way (tests compare the two).
    bool camera_packets = true;
    // Samples spread over the pixels by their noise (adaptive_sampling.h): spp × pixels samples in all, or
    // the time budget; the integrators whose samples start in a pixel (path, volpath, bdpt, direct, the debug
    // passes), in one process.
    AdaptiveSettings adaptive;
};

struct RenderResult {
    Image image;
    double seconds = 0;
    int spp = 0; // samples per pixel actually taken (adaptive sampling: their mean, rounded)
    // Adaptive sampling: the fewest and most samples a pixel took, the rounds, and the error level e at
    // which the last round stopped its pixels (adaptive_sampling.h).
    struct Adaptive {
        std::uint32_t min_spp = 0, max_spp = 0;
        int rounds = 0;
        double level = 0;
    };
    std::optional<Adaptive> adaptive;
    std::uint64_t samples = 0;
    std::uint64_t rays = 0;
    std::uint64_t nonfinite_samples =
        0; // NaN/Inf (or negative radiance) estimates: dropped, counted, never written
    int threads = 0;
    // Further images an integrator makes besides the render (bdpt's per-strategy images), each with the
    // file name it is written to (relative to the working directory, as pbrt-v4 writes them).
    struct NamedImage {
        std::string name;
        Image image;
    };
    std::vector<NamedImage> extra_images;
};

// An integrator that renders the whole image itself rather than one camera sample at a time (light
// tracing splats particles onto the film, photon mapping runs iterations): render() hands over to it.
class WholeImageIntegrator : public Integrator {
public:
    using Integrator::Integrator;
    virtual RenderResult render_image(const RenderOptions& options) const = 0;
    // Whether options.adaptive is honoured (volpath with its caustics: its camera paths are adaptive).
    virtual bool adapts_samples() const { return false; }
    // Not a per-camera-sample estimator.
    Radiance3 estimate(const Ray&, ThreadContext&) const override { return {}; }
};

// What every render loop derives from the options: the worker threads (0 asks for all the hardware's) and
// the sampler kind (an unknown name throws illum::Error naming the choices).
int render_threads(const RenderOptions& options);
SamplerKind render_sampler_kind(const RenderOptions& options);
// The sampler every thread copies: options' kind, settings and seed, spp samples per pixel over the
// scene's resolution.
Sampler make_sampler(const RenderOptions& options, int spp, Point2i resolution);

// Runs a render loop's passes: pass(k0, k1) renders this process's samples k0..k1-1 (of its share,
// render_group.h). Either all of the share's samples of options.spp at once, or, with a time budget,
// passes until the budget is spent (on rank 0's clock in a group): of one sample per pixel at first, then
// of twice as many each time (at most kMaxTimedPass), as long as the passes so far say the next one ends
// within the budget. (A pass renders each pixel's samples one after another, which is faster than one
// sample per pixel at a time: 161 samples per pixel in 10 s against 136 on scripts/many_lights.py.) In a
// group, where the ranks agree only on whether to go on, and with a preview, passes of one sample per pixel;
// after each of those preview->frame gets snapshot(k), the image after k passes. Returns the passes this
// process rendered.
template <class Pass, class Snapshot>
int run_passes(const RenderOptions& options, Progress& progress, Pass&& pass, Snapshot&& snapshot) {
    const SampleShare share = sample_share(options.group);
    const bool timed = options.time_budget > 0;
    const int n = share.count(options.spp);
    if (!timed && !options.preview) {
        pass(0, n);
        return n;
    }
    constexpr int kMaxTimedPass = 32;
    const bool growing = timed && !options.group && !options.preview;
    int k = 0, next = 1;
    bool more = timed || n > 0;
    while (more) {
        int size = 1;
        if (growing && k > 0) {
            double per_pass = progress.elapsed_seconds() / k;
            double remaining = options.time_budget - progress.elapsed_seconds();
            size = std::clamp(int(remaining / std::max(per_pass, 1e-9)), 1, next);
            next = std::min(2 * next, kMaxTimedPass);
        }
        pass(k, k + size);
        k += size;
        double fraction = timed ? progress.elapsed_seconds() / options.time_budget : double(k) / n;
        if (timed) progress.set_fraction(fraction);
        more = timed ? progress.elapsed_seconds() < options.time_budget : k < n;
        if (timed && options.group) more = options.group->broadcast(more);
        if (options.preview) options.preview->frame(snapshot(k), k, timed ? 0 : n, more ? fraction : 1.0);
    }
    return k;
}

// The samples of an adaptive round's unit of work (AdaptiveSchedule::round_runs).
inline constexpr std::uint64_t kAdaptiveWorkSamples = 1024;

// Adaptive sampling's rounds (adaptive_sampling.h) on `film`, the film of per-pixel estimates: round(s)
// renders each pixel's samples [s.from(x, y), s.to(x, y)) into it, snapshot(s) is the image after the
// rounds so far (s.taken() samples), for a preview. Every round plans for the whole render: options.spp ×
// pixels samples, or with a time budget those taken so far and as many as the time left allows at the rate so
// far. One process only.
template <class Round, class Snapshot>
AdaptiveSchedule run_adaptive_rounds(const RenderOptions& options, const PixelBounds& bounds,
                                     const Film& film, Progress& progress, Round&& round,
                                     Snapshot&& snapshot) {
    if (options.group)
        throw Error("adaptive sampling renders in one process: it cannot share its samples with other ranks "
                    "(mpirun or --share)");
    AdaptiveSchedule schedule(bounds, options.adaptive);
    const std::uint64_t pixels = schedule.pixels();
    const std::uint64_t budget = pixels * std::uint64_t(std::max(options.spp, 1));
    const bool timed = options.time_budget > 0;
    for (;;) {
        std::uint64_t added = 0;
        if (timed && schedule.rounds() >= 2) {
            const double elapsed = progress.elapsed_seconds(), left = options.time_budget - elapsed;
            if (!(left > 0)) break;
            // As many samples as the time left allows at the rate so far; if that makes no pixel double, the
            // least larger budget that does (up to twice the samples so far), so that the rounds go on until
            // the time is spent as run_passes' passes do.
            const std::uint64_t taken = schedule.taken();
            std::uint64_t extra = std::max(pixels, std::uint64_t(double(taken) / elapsed * left));
            while ((added = schedule.plan(film, taken + extra)) == 0 && extra < taken) extra *= 2;
        } else {
            added = schedule.plan(film, timed ? pixels * std::uint64_t(options.adaptive.min_spp) : budget);
        }
        if (added == 0) break;
        round(schedule);
        schedule.commit();
        const double fraction = timed ? std::min(1.0, progress.elapsed_seconds() / options.time_budget)
                                      : double(schedule.taken()) / double(budget);
        if (timed) progress.set_fraction(fraction);
        if (options.preview)
            options.preview->frame(snapshot(schedule), int(schedule.taken() / pixels), 0, fraction);
    }
    progress.finish();
    return schedule;
}
// A render's figures after adaptive rounds: the mean samples per pixel (rounded), the samples and the
// rounds' figures.
void record_adaptive(const AdaptiveSchedule& schedule, RenderResult& r);

// After the passes: sums the film's accumulators and r's counters (rays, dropped samples) over the group
// onto rank 0, and returns the samples per pixel the whole group took. Without a group, `passes`.
int sum_over_group(const RenderOptions& options, int passes, std::span<double> accumulators, RenderResult& r);

RenderResult render(const Scene& scene, const Integrator& integrator, const RenderOptions& options);

} // namespace illum
