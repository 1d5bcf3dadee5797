#include "illum/render/renderer.h"

#include <atomic>
#include <chrono>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <thread>

#include "illum/camera/film.h"
#include "illum/util/error.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int w, int h, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < h; y += size)
        for (int x = 0; x < w; x += size)
            tiles.push_back({x, y, std::min(x + size, w), std::min(y + size, h)});
    return tiles;
}

} // namespace

int render_threads(const RenderOptions& options) {
    return options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

SamplerKind render_sampler_kind(const RenderOptions& options) {
    std::optional<SamplerKind> kind = parse_sampler_kind(options.sampler);
    if (!kind) throw Error("unknown sampler \"" + options.sampler + "\" (use sobol or independent)");
    return *kind;
}

int sum_over_group(const RenderOptions& options, int passes, std::span<double> accumulators, RenderResult& r) {
    RenderGroup* group = options.group;
    if (!group) return passes;
    group->sum(accumulators, false);
    r.rays = sum_counter(group, r.rays);
    r.nonfinite_samples = sum_counter(group, r.nonfinite_samples);
    return options.time_budget > 0 ? passes * group->size() : options.spp;
}

RenderResult render(const Scene& scene, const Integrator& integrator, const RenderOptions& options) {
    if (options.spp <= 0 && options.time_budget <= 0) throw Error("samples per pixel must be positive");
    if (auto* whole = dynamic_cast<const WholeImageIntegrator*>(&integrator))
        return whole->render_image(options);
    const int w = scene.width, h = scene.height;
    int threads = render_threads(options);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    tbb::task_arena arena(threads);

    Film film(w, h);
    std::vector<Tile> tiles = make_tiles(w, h, options.tile_size);
    Sampler prototype(render_sampler_kind(options), options.spp > 0 ? options.spp : 1, options.seed);
    tbb::enumerable_thread_specific<ThreadContext> contexts([&] { return ThreadContext(prototype); });
    std::atomic<std::uint64_t> nonfinite{0};
    const bool reject_negative = !integrator.signed_values();
    // A debug pass's values are RGB in either mode and do not pass through the sensor.
    const bool spectral = options.spectral && integrator.radiometric();
    const bool radiometric = integrator.radiometric();
    const bool dispersive_camera = spectral && scene.camera->is_dispersive();

    const bool timed = options.time_budget > 0;
    std::uint64_t pixels = std::uint64_t(w) * h;
    const SampleShare share = sample_share(options.group);
    Progress progress("render", timed ? 0 : pixels * std::uint64_t(share.count(options.spp)), "samples",
                      options.quiet);

    // Renders this share's samples k0..k1-1 (global indices share.index(k)) of every pixel.
    auto pass = [&](int k0, int k1) {
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const auto& range) {
                ThreadContext& tc = contexts.local();
                for (std::size_t ti = range.begin(); ti != range.end(); ++ti) {
                    const Tile& t = tiles[ti];
                    for (int y = t.y0; y < t.y1; ++y)
                        for (int x = t.x0; x < t.x1; ++x)
                            for (int k = k0; k < k1; ++k) {
                                tc.sampler.start_pixel_sample({x, y}, share.index(k));
                                FilterSample fs = scene.filter->sample(tc.sampler.get_pixel_2d());
                                Point2f p_film{x + 0.5f + fs.offset.x, y + 0.5f + fs.offset.y};
                                Point2f u_lens = tc.sampler.get_2d();
                                tc.lambda = spectral ? SampledWavelengths::sample_visible(tc.sampler.get_1d(),
                                                                                          scene.color_space)
                                                     : SampledWavelengths::rgb_mode();
                                // RGB mode: the camera sees the d line. A dispersive lens sends each
                                // wavelength its own way: the path keeps the hero only. A vignetted sample
                                // adds zero radiance but still counts (its filter weight goes to the pixel).
                                if (dispersive_camera) tc.lambda.terminate_secondary();
                                std::optional<CameraRay> cr = scene.camera->generate_ray(
                                    p_film, u_lens, spectral ? tc.lambda.hero() : kDLineNm);
                                // Motion blur: the sample's time, shared by every ray of its path.
                                if (cr && scene.has_motion)
                                    cr->ray =
                                        scene.camera_ray_at(cr->ray, scene.sample_time(tc.sampler.get_1d()));
                                Radiance3 v(0.0f);
                                if (cr) v = integrator.estimate(cr->ray, tc) * cr->weight;
                                tc.arena.reset();
                                if (!v.is_finite() || (reject_negative && v.has_negative())) {
                                    ++nonfinite;
                                    v = Radiance3(0.0f);
                                }
                                Color3 c = radiometric ? scene.sensor.to_rgb(v, tc.lambda) : v.rgb();
                                film.add_sample(x, y, c, fs.weight);
                            }
                    progress.add(std::uint64_t(t.x1 - t.x0) * (t.y1 - t.y0) * (k1 - k0));
                }
            });
        });
    };

    const int passes = run_passes(options, progress, pass, [&](int) { return film.resolve(); });
    progress.finish();

    RenderResult r;
    for (auto& tc : contexts) r.rays += tc.rays;
    r.nonfinite_samples = nonfinite;
    r.spp = sum_over_group(options, passes, film.accumulators(), r);
    r.seconds = progress.elapsed_seconds();
    r.image = film.resolve();
    r.samples = pixels * std::uint64_t(r.spp);
    r.threads = threads;
    return r;
}

} // namespace illum
