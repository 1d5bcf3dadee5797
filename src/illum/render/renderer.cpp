#include "illum/render/renderer.h"

#include <atomic>
#include <chrono>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <thread>

#include "illum/camera/film.h"
#include "illum/render/render_arena.h"
#include "illum/util/error.h"
#include "illum/util/in_place.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

// A camera ray with its differentials, scaled to the spacing of the pixel's samples.
std::optional<CameraRay> camera_ray_differential(const Scene& scene, Point2f p_film, Point2f u_lens,
                                                 float lambda, float scale, RayDifferentials* rd) {
    std::optional<CameraRay> cr = scene.camera->generate_ray_differential(p_film, u_lens, lambda, rd);
    if (!cr) rd->valid = false;
    if (rd->valid) rd->scale(cr->ray, scale);
    return cr;
}

// The differentials of a moving camera's ray, moved as the ray is (Scene::camera_ray_at).
void move_differentials(const Scene& scene, float time, RayDifferentials* rd) {
    Ray rx = scene.camera_ray_at(Ray{rd->rx_origin, rd->rx_direction}, time);
    Ray ry = scene.camera_ray_at(Ray{rd->ry_origin, rd->ry_direction}, time);
    rd->rx_origin = rx.o, rd->rx_direction = rx.d;
    rd->ry_origin = ry.o, rd->ry_direction = ry.d;
}

struct Tile {
    int x0, y0, x1, y1;
};

// Tiles of the pixels b keeps, in the full image's raster.
std::vector<Tile> make_tiles(const PixelBounds& b, int size) {
    std::vector<Tile> tiles;
    for (int y = b.y0; y < b.y1; y += size)
        for (int x = b.x0; x < b.x1; x += size)
            tiles.push_back({x, y, std::min(x + size, b.x1), std::min(y + size, b.y1)});
    return tiles;
}

// An adaptive round's work: its runs of pixels (AdaptiveSchedule::round_runs) as tiles one row high.
std::vector<Tile> round_tiles(const AdaptiveSchedule& schedule) {
    std::vector<Tile> tiles;
    for (const AdaptiveSchedule::Run& run : schedule.round_runs(kAdaptiveWorkSamples))
        tiles.push_back({run.x0, run.y, run.x1, run.y + 1});
    return tiles;
}

// A whole-image integrator's result, cropped to the film's pixel bounds. Light tracing, BDPT and photon
// mapping render the whole film: their light paths splat onto any pixel, so the kept pixels are only
// right if every pixel's paths were traced (pbrt-v4 traces the crop's alone, which leaves out the light
// reaching the crop through the splats of paths started elsewhere).
// An image already of the bounds' size (volpath's caustics sum render()'s cropped camera paths with their
// own crop) stays.
RenderResult cropped(RenderResult r, const Scene& scene) {
    const PixelBounds b = scene.output_bounds();
    auto keep = [&](Image& image) {
        if (image.width() == scene.width && image.height() == scene.height) image = crop(image, b);
    };
    keep(r.image);
    for (auto& extra : r.extra_images) keep(extra.image);
    return r;
}

} // namespace

int render_threads(const RenderOptions& options) {
    return options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

SamplerKind render_sampler_kind(const RenderOptions& options) {
    std::optional<SamplerKind> kind = parse_sampler_kind(options.sampler);
    if (!kind)
        throw Error("unknown sampler \"" + options.sampler +
                    "\" (use zsobol, sobol, paddedsobol, halton, pmj02bn, stratified or independent)");
    return *kind;
}

Sampler make_sampler(const RenderOptions& options, int spp, Point2i resolution) {
    SamplerSettings settings = options.sampler_settings;
    settings.resolution = resolution;
    return Sampler(render_sampler_kind(options), spp, options.seed, settings);
}

void record_adaptive(const AdaptiveSchedule& schedule, RenderResult& r) {
    const std::uint64_t pixels = schedule.pixels();
    r.samples = schedule.taken();
    r.spp = int((r.samples + pixels / 2) / pixels);
    r.adaptive = RenderResult::Adaptive{schedule.min_taken(), schedule.max_taken(), schedule.rounds(),
                                        schedule.level()};
}

int sum_over_group(const RenderOptions& options, int passes, std::span<double> accumulators,
                   RenderResult& r) {
    RenderGroup* group = options.group;
    if (!group) return passes;
    group->sum(accumulators, false);
    r.rays = sum_counter(group, r.rays);
    r.nonfinite_samples = sum_counter(group, r.nonfinite_samples);
    return options.time_budget > 0 ? passes * group->size() : options.spp;
}

RenderResult render(const Scene& scene, const Integrator& integrator, const RenderOptions& options) {
    if (options.spp <= 0 && options.time_budget <= 0) throw Error("samples per pixel must be positive");
    const PixelBounds bounds = scene.output_bounds();
    if (auto* whole = dynamic_cast<const WholeImageIntegrator*>(&integrator)) {
        if (options.adaptive.enabled && !whole->adapts_samples())
            throw Error(
                "adaptive sampling works with path, volpath, bdpt, direct and the debug passes, whose "
                "samples start in a pixel, not with lightpath, sppm or vcm, whose light paths or "
                "iterations serve every pixel at once");
        return cropped(whole->render_image(options), scene);
    }
    // The film covers the full image (a preview shows the kept pixels in place); only the pixels of
    // `bounds` are rendered, each from its own (seed, pixel, index) sample sequence, so they equal the
    // same pixels of an uncropped render.
    const int w = scene.width, h = scene.height;
    int threads = render_threads(options);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);

    Film film(w, h);
    const std::vector<Tile> tiles = make_tiles(bounds, options.tile_size);
    const Sampler prototype = make_sampler(options, options.spp > 0 ? options.spp : 1, {w, h});
    tbb::enumerable_thread_specific<ThreadContext> contexts([&] { return ThreadContext(prototype); });
    std::atomic<std::uint64_t> nonfinite{0};
    const bool reject_negative = !integrator.signed_values();
    // A debug pass's values are RGB in either mode and do not pass through the sensor.
    const bool spectral = options.spectral && integrator.radiometric();
    const bool radiometric = integrator.radiometric();
    const bool dispersive_camera = spectral && scene.camera->is_dispersive();
    const bool uses_lens = scene.camera->uses_lens_sample();
    // pbrt-v4 scales the differentials to the samples' spacing only when the samples are jittered.
    const float diff_scale =
        scene.request.disable_pixel_jitter ? 1.0f : ray_differential_scale(options.spp > 0 ? options.spp : 1);

    const bool timed = options.time_budget > 0;
    std::uint64_t pixels = std::uint64_t(bounds.width()) * bounds.height();
    const SampleShare share = sample_share(options.group);
    Progress progress("render", timed ? 0 : pixels * std::uint64_t(share.count(options.spp)), "samples",
                      options.quiet);

    // A pixel sample up to its camera ray: the filter's sample, the wavelengths, the ray (and its
    // differentials, in tc) at the sample's time.
    struct CameraSample {
        FilterSample fs;
        std::optional<CameraRay> cr;
        SampledWavelengths lambda;
        RayDifferentials rd;
        Sampler::Position position;
    };
    auto start_sample = [&](ThreadContext& tc, int x, int y, int index, CameraSample* s) {
        tc.sampler.start_pixel_sample({x, y}, index);
        s->fs = scene.pixel_filter_sample(tc.sampler.get_pixel_2d());
        Point2f p_film{x + 0.5f + s->fs.offset.x, y + 0.5f + s->fs.offset.y};
        Point2f u_lens = tc.sampler.get_2d_if(uses_lens);
        assign_in_place(tc.lambda, [&] { return scene.sample_wavelengths(spectral, tc.sampler); });
        // RGB mode: the camera sees the d line. A dispersive lens sends each wavelength its own way: the
        // path keeps the hero only. A vignetted sample adds zero radiance but still counts (its filter
        // weight goes to the pixel).
        if (dispersive_camera) tc.lambda.terminate_secondary();
        const float lambda_cam = spectral ? tc.lambda.hero() : kDLineNm;
        if (scene.texture_filtering) [[unlikely]]
            s->cr = camera_ray_differential(scene, p_film, u_lens, lambda_cam, diff_scale,
                                            &tc.camera_differentials);
        else
            assign_in_place(s->cr, [&] { return scene.camera->generate_ray(p_film, u_lens, lambda_cam); });
        // Motion blur: the sample's time, shared by every ray of its path.
        if (s->cr && scene.has_motion) {
            float time = scene.sample_time(tc.sampler.get_1d());
            s->cr->ray = scene.camera_ray_at(s->cr->ray, time);
            if (tc.camera_differentials.valid) move_differentials(scene, time, &tc.camera_differentials);
        }
    };
    // The rest of the sample: the integrator's estimate along the camera ray, added to the film.
    auto finish_sample = [&](ThreadContext& tc, int x, int y, const CameraSample& s) {
        Radiance3 v(0.0f);
        if (s.cr) v = integrator.estimate(s.cr->ray, tc) * s.cr->weight;
        tc.primed.pending = false;
        tc.arena.reset();
        if (!v.is_finite() || (reject_negative && v.has_negative())) {
            ++nonfinite;
            v = Radiance3(0.0f);
        }
        Color3 c = radiometric ? scene.sensor.to_film(v, tc.lambda) : v.rgb();
        film.add_sample(x, y, c, s.fs.weight);
    };
    // Camera rays in packets: the samples of a tile's row (pixel by pixel, each pixel's samples in turn, the
    // order they reach the film in) are started up to kPacket at a time, their camera rays traced together
    // (the samples of a pixel, or neighbouring pixels, are coherent), and each sample resumed with its hit.
    // The same samples in the same order: the image is the one sample-by-sample tracing gives.
    constexpr int kPacket = Accelerator::kPacket;
    const bool packets =
        options.camera_packets && integrator.starts_at_camera_hit() && scene.accelerator.packets_supported();

    // Renders this share's samples [first(x, y), last(x, y)) of each pixel of the tiles (global indices
    // share.index(k)).
    auto render_samples = [&](const std::vector<Tile>& tiles, auto&& first, auto&& last) {
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles.size(), 1), [&](const auto& range) {
                ThreadContext& tc = contexts.local();
                CameraSample batch[kPacket];
                Ray rays[kPacket];
                Accelerator::Found found[kPacket];
                int ray_sample[kPacket], sample_x[kPacket];
                for (std::size_t ti = range.begin(); ti != range.end(); ++ti) {
                    const Tile& t = tiles[ti];
                    std::uint64_t samples = 0;
                    for (int y = t.y0; y < t.y1; ++y) {
                        if (!packets) {
                            for (int x = t.x0; x < t.x1; ++x)
                                for (int k = first(x, y), k1 = last(x, y); k < k1; ++k, ++samples) {
                                    start_sample(tc, x, y, share.index(k), &batch[0]);
                                    finish_sample(tc, x, y, batch[0]);
                                }
                            continue;
                        }
                        // The row's samples, pixel by pixel and each pixel's in turn, up to kPacket at a
                        // time.
                        int x = t.x0, k = first(x, y), k_end = last(x, y);
                        for (;;) {
                            int n = 0, n_rays = 0;
                            for (; n < kPacket; ++n) {
                                while (k >= k_end && ++x < t.x1) k = first(x, y), k_end = last(x, y);
                                if (x >= t.x1) break;
                                CameraSample& s = batch[n];
                                start_sample(tc, x, y, share.index(k++), &s);
                                sample_x[n] = x;
                                s.lambda = tc.lambda;
                                if (scene.texture_filtering) s.rd = tc.camera_differentials;
                                s.position = tc.sampler.position();
                                if (s.cr) {
                                    ray_sample[n_rays] = n;
                                    rays[n_rays++] = s.cr->ray;
                                }
                            }
                            if (n == 0) break;
                            samples += std::uint64_t(n);
                            // A lone ray goes the integrator's own way.
                            const std::uint32_t hits =
                                n_rays > 1 ? scene.accelerator.find_packet(rays, n_rays, found) : 0;
                            for (int j = 0, r = 0; j < n; ++j) {
                                const CameraSample& s = batch[j];
                                tc.sampler.resume(s.position);
                                tc.lambda = s.lambda;
                                if (scene.texture_filtering) tc.camera_differentials = s.rd;
                                if (r < n_rays && ray_sample[r] == j) {
                                    if (n_rays > 1) {
                                        tc.primed.pending = true;
                                        tc.primed.hit = (hits >> r) & 1u;
                                        tc.primed.ray = rays[r];
                                        tc.primed.found = found[r];
                                    }
                                    ++r;
                                }
                                finish_sample(tc, sample_x[j], y, s);
                            }
                        }
                    }
                    progress.add(samples);
                }
            });
        });
    };
    // Samples k0..k1-1 of every pixel.
    auto pass = [&](int k0, int k1) {
        render_samples(
            tiles, [k0](int, int) { return k0; }, [k1](int, int) { return k1; });
    };

    RenderResult r;
    // This process's counters (before they are summed over a group).
    auto count = [&] {
        for (auto& tc : contexts) r.rays += tc.rays;
        r.nonfinite_samples = nonfinite;
    };
    if (options.adaptive.enabled) {
        const AdaptiveSchedule schedule = run_adaptive_rounds(
            options, bounds, film, progress,
            [&](const AdaptiveSchedule& s) {
                render_samples(
                    round_tiles(s), [&](int x, int y) { return s.from(x, y); },
                    [&](int x, int y) { return s.to(x, y); });
            },
            [&](const AdaptiveSchedule&) { return film.resolve(); });
        count();
        record_adaptive(schedule, r);
    } else {
        const int passes = run_passes(options, progress, pass, [&](int) { return film.resolve(); });
        progress.finish();
        count();
        r.spp = sum_over_group(options, passes, film.accumulators(), r);
        r.samples = pixels * std::uint64_t(r.spp);
    }
    r.seconds = progress.elapsed_seconds();
    r.image = crop(film.resolve(), bounds);
    r.threads = threads;
    return r;
}

} // namespace illum
