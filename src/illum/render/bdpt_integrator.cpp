#include "illum/render/bdpt_integrator.h"

#include "illum/render/chunked_schedule.h"

#include <algorithm>
#include <fmt/core.h>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_group.h>
#include <thread>
#include <vector>

#include "illum/camera/film.h"
#include "illum/camera/splat_film.h"
#include "illum/render/path_vertex.h"
#include "illum/render/render_arena.h"
#include "illum/util/error.h"
#include "illum/util/in_place.h"
#include "illum/util/line_aligned.h"
#include "illum/util/progress.h"

namespace illum {

namespace {

// One camera sample's estimate of its pixel (strategies t >= 2), in the output colour space.
struct CameraEstimate {
    std::uint32_t pixel;
    Color3 value;
    float weight;
};

// What one chunk of pixel samples produces, added to the films in chunk order.
struct ChunkOutput {
    // Written by one thread while the others write theirs: in lines of their own (line_aligned.h).
    LineAlignedVector<CameraEstimate> estimates;
    LineAlignedVector<Splat> splats;
    // visualizestrategies / visualizeweights: each strategy's contribution, splatted into its own image.
    LineAlignedVector<std::pair<int, Splat>> strategy_splats;
    int dropped = 0;
};

// pbrt-v4's numbering of the strategy images: depth d = s + t - 2 holds s = 0..d+2, after the images of
// the shallower depths.
int strategy_index(int s, int t) {
    int depth = s + t - 2;
    return s + depth * (5 + depth) / 2;
}

// The subpaths' storage, once per thread: maxdepth + 2 camera and maxdepth + 1 light vertices.
struct Subpaths {
    LineAlignedVector<PathVertex> camera, light;
    PathVertex sampled; // the endpoint a strategy samples (s = 1: a light point, t = 1: the camera's)
    // The weights' running sums over each subpath (subpath_sums), so that a connection's weight costs O(1)
    // beyond the joint.
    LineAlignedVector<float> camera_tail, light_tail;
};

float remap0(float f) { return f != 0 ? f : 1.0f; }

// The running sums of mis_weight's loops over one subpath, as vcm_mis.h's subpath_tails (without merging):
// tail[i] is the loop's sum over the vertices i, i - 1, ... down to the subpath's end, with the ratio 1
// before vertex i, for the strategies that move the connection there. Camera subpath: vertex 0 is on the
// camera (tail[0] = 0); light subpath: vertex 0 is on the light. Only the subpath's own densities enter,
// which no connection changes below the joint's two neighbours.
void subpath_sums(const PathVertex* v, int n, bool camera, float* tail) {
    float below = 0;
    for (int i = 0; i < n; ++i) {
        if (camera && i == 0) {
            tail[0] = 0;
            continue;
        }
        const bool delta_before = i > 0 ? v[i - 1].delta : v[0].is_delta_light();
        const float term = !v[i].delta && !delta_before ? 1.0f : 0.0f;
        tail[i] = remap0(v[i].pdf_rev) / remap0(v[i].pdf_fwd) * (term + below);
        below = tail[i];
    }
}

// The balance heuristic for strategy (s, t) (Veach 1997 §10.2.1, eq. 10.9): with p_i the density of the
// path under the strategy with i light vertices, w = p_s / Σ p_i, evaluated as 1 / (1 + Σ_{i≠s} p_i/p_s)
// where the ratios follow from the vertices' densities: moving the connection one vertex towards the
// camera multiplies the ratio by pdf_rev / pdf_fwd of the camera vertex passed, and likewise towards the
// light. The reverse densities at the connection's two ends and their predecessors depend on the
// strategy: they are computed here and used in place of the stored ones (the subpaths are not written).
// `sampled`, when given, is the strategy's own endpoint: the light point of s = 1 (in lv[0]'s place) or
// the camera point of t = 1 (in cv[0]'s place). at_qs / at_pt: the connection's ends' scattering towards
// each other where connect() evaluated it (join_densities). Beyond the joint's two neighbours on each side
// the sums are the subpaths' running sums (light_tail, camera_tail: subpath_sums), whose terms are the
// loops' own.
float mis_weight(const PathContext& ctx, const PathVertex* lv, const PathVertex* cv, int s, int t,
                 const PathVertex* sampled, const EndScattering* at_qs, const EndScattering* at_pt,
                 const float* light_tail, const float* camera_tail) {
    if (s + t == 2) return 1;
    const PathVertex* l0 = s == 1 && sampled ? sampled : lv;
    const PathVertex* qs = s > 0 ? (s == 1 ? l0 : &lv[s - 1]) : nullptr;
    const PathVertex* pt = t > 0 ? (t == 1 && sampled ? sampled : &cv[t - 1]) : nullptr;
    const PathVertex* qs_m = s > 1 ? &lv[s - 2] : nullptr;
    const PathVertex* pt_m = t > 1 ? &cv[t - 2] : nullptr;

    // The reverse densities next to the connection, used in place of the stored ones.
    const JoinDensities j = join_densities(ctx, qs, qs_m, *pt, pt_m, at_qs, at_pt);
    if (!j.joined) return 0;

    float sum = 0, ri = 1;
    for (int i = t - 1; i > 0; --i) {
        if (i == t - 3) {
            sum += ri * camera_tail[i];
            break;
        }
        const float rev = i == t - 1 ? j.pt_rev : (i == t - 2 ? j.pt_m_rev : cv[i].pdf_rev);
        ri *= remap0(rev) / remap0(cv[i].pdf_fwd);
        const bool delta = i == t - 1 ? false : cv[i].delta;
        if (!delta && !cv[i - 1].delta) sum += ri;
    }
    ri = 1;
    for (int i = s - 1; i >= 0; --i) {
        if (i == s - 3) { // s >= 3: lv[0] is the subpath's own
            sum += ri * light_tail[i];
            break;
        }
        const PathVertex& v = i == 0 ? *l0 : lv[i];
        const float rev = i == s - 1 ? j.qs_rev : (i == s - 2 ? j.qs_m_rev : v.pdf_rev);
        ri *= remap0(rev) / remap0(v.pdf_fwd);
        const bool delta = i == s - 1 ? false : v.delta;
        const bool delta_before = i > 0 ? (i == 1 ? l0->delta : lv[i - 1].delta) : l0->is_delta_light();
        if (!delta && !delta_before) sum += ri;
    }
    return 1 / (1 + sum);
}

// The contribution of strategy (s, t), MIS-weighted, and its weight in *weight. t = 1 sets *p_raster (a
// splat). `sampled` is scratch for the endpoint that s = 1 and t = 1 sample.
SampledSpectrum connect(const PathContext& ctx, const Subpaths& sp, int s, int t, int ch, bool camera_delta,
                        PathVertex* sampled, Point2f* p_raster, float* weight) {
    const PathVertex* lv = sp.light.data();
    const PathVertex* cv = sp.camera.data();
    const Scene& scene = ctx.scene;
    Sampler& sampler = ctx.tc.sampler;
    // A light vertex at infinity ends the camera subpath; only s = 0 uses it.
    if (t > 1 && s != 0 && cv[t - 1].type == VertexType::Light) return SampledSpectrum(0.0f);

    SampledSpectrum l(0.0f);
    bool have_sampled = false;
    EndScattering at_qs, at_pt; // what connect evaluates at the ends (none: has_pdfs false)
    if (s == 0) {
        const PathVertex& pt = cv[t - 1];
        if (pt.is_light()) l = vertex_le(ctx, pt, cv[t - 2]) * pt.beta;
    } else if (t == 1) {
        const PathVertex& qs = lv[s - 1];
        if (camera_delta || !qs.is_connectible()) return SampledSpectrum(0.0f);
        Point2f u = sampler.get_2d_if(scene.camera->uses_lens_sample());
        std::optional<CameraWiSample> cs = scene.camera_sample_wi(qs.p, u, ctx.time);
        if (!cs) return SampledSpectrum(0.0f);
        *p_raster = cs->p_raster;
        // Every field a camera vertex reads (the scratch vertex may hold a light point from before).
        sampled->type = VertexType::Camera;
        sampled->delta = false;
        sampled->p = cs->p_lens;
        sampled->p_error = Vector3f{};
        sampled->ng = sampled->ns = Normal3f{};
        sampled->medium = scene.camera_medium;
        sampled->light = nullptr;
        sampled->pdf_fwd = sampled->pdf_rev = 0;
        sampled->beta = SampledSpectrum((cs->we / cs->pdf).value);
        have_sampled = true;
        const Segment to_camera = segment(qs, *sampled);
        if (!(to_camera.inv_d2 > 0)) return SampledSpectrum(0.0f);
        assign_in_place(at_qs, [&] { return end_scattering(qs, to_camera.w, TransportMode::Importance); });
        l = qs.beta * at_qs.f * sampled->beta;
        if (qs.on_surface()) l *= std::abs(dot(cs->wi, Vector3f(qs.ns)));
        if (!l.is_black()) l *= connection_transmittance(ctx, qs, *sampled, ch);
    } else if (s == 1) {
        const PathVertex& pt = cv[t - 1];
        if (!pt.is_connectible()) return SampledSpectrum(0.0f);
        float u_light = sampler.get_1d();
        Point2f u = sampler.get_2d();
        if (!connect_sampled_light(ctx, pt, u_light, u, ch, sampled, &l, &at_pt))
            return SampledSpectrum(0.0f);
        have_sampled = true;
    } else {
        const PathVertex& qs = lv[s - 1];
        const PathVertex& pt = cv[t - 1];
        if (!qs.is_connectible() || !pt.is_connectible()) return SampledSpectrum(0.0f);
        const Segment joint = segment(qs, pt);
        if (!(joint.inv_d2 > 0)) return SampledSpectrum(0.0f);
        assign_in_place(at_qs, [&] { return end_scattering(qs, joint.w, TransportMode::Importance); });
        assign_in_place(at_pt, [&] { return end_scattering(pt, -joint.w, TransportMode::Radiance); });
        l = qs.beta * at_qs.f * at_pt.f * pt.beta;
        if (!l.is_black()) l *= connect_g(ctx, qs, pt, joint, ch);
    }
    if (l.is_black()) return l;

    // The strategy's sampled endpoint stands in for the subpath's own while the weight is computed.
    const float w = mis_weight(ctx, lv, cv, s, t, have_sampled ? sampled : nullptr, &at_qs, &at_pt,
                               sp.light_tail.data(), sp.camera_tail.data());
    *weight = w;
    return l * w;
}

} // namespace

BDPTIntegrator::BDPTIntegrator(const Scene& scene, int max_depth)
    : WholeImageIntegrator(scene), max_depth_(max_depth < 0 ? kUnboundedDepth : max_depth) {
    if (!scene.camera || !scene.camera->has_importance())
        throw Error(
            scene.camera_loc,
            fmt::format("integrator \"bdpt\" cannot use camera \"{}\": it needs a perspective camera or an "
                        "orthographic one without a lens (the realistic and spherical cameras and a "
                        "thin-lens orthographic one have no importance function)",
                        scene.camera_type));
}

namespace {

// The camera film's image plus the light subpaths' splats (t = 1) after `per_pixel` samples per pixel (each
// traced one light subpath).
Image with_splats(Image image, const SplatFilm& splats, double per_pixel) {
    Image s = splats.resolve(per_pixel);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) image.data()[i] += s.data()[i];
    return image;
}

} // namespace

RenderResult BDPTIntegrator::render_image(const RenderOptions& options) const {
    const int w = scene_.width, h = scene_.height;
    const std::size_t pixels = std::size_t(w) * h;
    int threads = render_threads(options);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);

    const Sampler prototype = make_sampler(options, options.spp > 0 ? options.spp : 1, {w, h});
    tbb::enumerable_thread_specific<ThreadContext> contexts([&] { return ThreadContext(prototype); });
    tbb::enumerable_thread_specific<Subpaths> storage([&] {
        Subpaths sp;
        sp.camera.resize(std::size_t(max_depth_) + 2);
        sp.light.resize(std::size_t(max_depth_) + 1);
        sp.camera_tail.resize(sp.camera.size());
        sp.light_tail.resize(sp.light.size());
        return sp;
    });
    Film film(w, h);
    SplatFilm splat_film(w, h, *scene_.filter);
    const bool spectral = options.spectral;
    const Camera& camera = *scene_.camera;
    const bool dispersive_camera = spectral && camera.is_dispersive();
    const bool camera_delta = dynamic_cast<const OrthographicCamera*>(&camera) != nullptr;
    Point3f scene_center;
    float scene_radius = 0;
    scene_.accelerator.bounds().bounding_sphere(&scene_center, &scene_radius);
    const int max_depth = max_depth_;
    const bool visualize_weights = scene_.request.bdpt_visualize_weights;
    const bool visualize = visualize_weights || scene_.request.bdpt_visualize_strategies;
    // The strategy images splat every strategy, the camera's too, normalised by the samples per pixel: they
    // need every pixel to take the same number.
    if (visualize && options.adaptive.enabled)
        throw Error("bdpt's visualizestrategies and visualizeweights images need the same samples in every "
                    "pixel: they cannot be combined with adaptive sampling");
    // One splat film per strategy image (pbrt-v4's weightFilms), for depths 0..maxdepth.
    std::vector<SplatFilm> strategy_films;
    if (visualize)
        for (int i = 0; i < strategy_index(0, max_depth + 3); ++i)
            strategy_films.emplace_back(w, h, *scene_.filter);

    // One pixel sample: both subpaths, then every strategy.
    auto trace = [&](ThreadContext& tc, Subpaths& sp, int x, int y, ChunkOutput& out) {
        Sampler& sampler = tc.sampler;
        tc.arena.reset();
        FilterSample fs = scene_.pixel_filter_sample(sampler.get_pixel_2d());
        Point2f p_film{x + 0.5f + fs.offset.x, y + 0.5f + fs.offset.y};
        Point2f u_lens = sampler.get_2d_if(camera.uses_lens_sample());
        assign_in_place(tc.lambda, [&] { return scene_.sample_wavelengths(spectral, sampler); });
        if (dispersive_camera) tc.lambda.terminate_secondary();
        const std::uint32_t pixel = std::uint32_t(y) * std::uint32_t(w) + std::uint32_t(x);
        std::optional<CameraRay> cr =
            camera.generate_ray(p_film, u_lens, spectral ? tc.lambda.hero() : kDLineNm);
        // The free-flight channels of the two subpaths and the generator for tracking steps.
        const int ch_camera = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
        const int ch_light = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
        PCG32 rng;
        {
            float a = sampler.get_1d(), b = sampler.get_1d();
            rng.set_sequence(hash(std::uint32_t(a * 0x1p32f), std::uint32_t(b * 0x1p32f)));
        }
        if (!cr) {
            out.estimates.push_back({pixel, Color3(0.0f), fs.weight});
            return;
        }
        // Motion blur: the sample's time, shared by both subpaths and their connections.
        if (scene_.has_motion) cr->ray = scene_.camera_ray_at(cr->ray, scene_.sample_time(sampler.get_1d()));
        PathContext ctx{scene_, tc, rng, scene_radius, cr->ray.time};
        PathVertex* cv = sp.camera.data();
        PathVertex* lv = sp.light.data();

        // The camera subpath.
        assign_in_place(cv[0], [] { return PathVertex{}; });
        cv[0].type = VertexType::Camera;
        cv[0].p = cr->ray.o;
        cv[0].medium = scene_.camera_medium;
        cv[0].beta = SampledSpectrum(cr->weight);
        cv[0].delta = camera_delta;
        Ray ray = cr->ray;
        ray.medium = scene_.camera_medium;
        float pdf_dir = scene_.camera_pdf_we(ray).dir.value;
        int n_camera = 1 + walk(ctx, ray, cv[0].beta, pdf_dir, max_depth + 1, TransportMode::Radiance,
                                ch_camera, cv + 1);

        // The light subpath.
        float u_light = sampler.get_1d();
        Point2f u_pos = sampler.get_2d(), u_dir = sampler.get_2d();
        int n_light = trace_light_subpath(ctx, u_light, u_pos, u_dir, max_depth, ch_light, lv);
        subpath_sums(cv, n_camera, true, sp.camera_tail.data());
        subpath_sums(lv, n_light, false, sp.light_tail.data());

        // The wavelengths are final once both subpaths are traced (a dispersive interface terminates the
        // secondary ones during a walk; connections leave them as they are).
        const FilmResponse response(scene_.sensor, tc.lambda);
        SampledSpectrum l(0.0f);
        // s = 1 samples a light of its own, so it runs even when the light subpath is empty (a photon that
        // carries nothing: an alpha-masked point, a portal light's photon whose line misses the portal).
        for (int t = 1; t <= n_camera; ++t)
            for (int s = 0; s <= std::max(n_light, 1); ++s) {
                int depth = s + t - 2;
                if ((s == 1 && t == 1) || depth < 0 || depth > max_depth) continue;
                Point2f p_raster;
                float w = 0;
                SampledSpectrum c =
                    connect(ctx, sp, s, t, ch_camera, camera_delta, &sp.sampled, &p_raster, &w);
                if (c.is_black()) continue;
                if (!c.is_finite() || c.has_negative()) {
                    ++out.dropped;
                    continue;
                }
                if (visualize) {
                    // pbrt-v4: the weighted contribution, or the unweighted one (the strategy alone).
                    SampledSpectrum v = visualize_weights ? c : (w > 0 ? c / w : SampledSpectrum(0.0f));
                    out.strategy_splats.push_back(
                        {strategy_index(s, t), {t == 1 ? p_raster : p_film, response.film(Radiance3(v))}});
                }
                if (t == 1)
                    out.splats.push_back({p_raster, response.film(Radiance3(c))});
                else
                    l += c;
            }
        out.estimates.push_back({pixel, response.film(Radiance3(l)), fs.weight});
    };

    std::uint64_t nonfinite = 0;
    const bool timed = options.time_budget > 0;
    Progress progress("render",
                      timed ? 0 : pixels * std::uint64_t(sample_share(options.group).count(options.spp)),
                      "samples", options.quiet);
    auto clear = [](ChunkOutput& out) {
        out.estimates.clear();
        out.splats.clear();
        out.strategy_splats.clear();
        out.dropped = 0;
    };
    auto apply = [&](const ChunkOutput& o) {
        for (const CameraEstimate& e : o.estimates)
            film.add_sample(int(e.pixel % std::uint32_t(w)), int(e.pixel / std::uint32_t(w)), e.value,
                            e.weight);
        for (const Splat& sp : o.splats) splat_film.add_splat(sp);
        for (const auto& [i, sp] : o.strategy_splats) strategy_films[std::size_t(i)].add_splat(sp);
        nonfinite += std::uint64_t(o.dropped);
    };
    RenderResult r;
    double per_pixel = 0; // samples per pixel, each with its light subpath: the splats' normalisation
    if (options.adaptive.enabled) {
        // Adaptive sampling: the camera estimates decide where samples go; every sample traces its light
        // subpath as always, so the splats stay normalised by the samples in all.
        const AdaptiveSchedule schedule = run_adaptive_rounds(
            options, PixelBounds::full(w, h), film, progress,
            [&](const AdaptiveSchedule& s) {
                const auto runs = s.round_runs(kAdaptiveWorkSamples);
                run_waves<ChunkOutput>(
                    arena, runs.size(),
                    [&](ChunkOutput& out, std::size_t k) {
                        ThreadContext& tc = contexts.local();
                        Subpaths& sp = storage.local();
                        clear(out);
                        std::uint64_t n = 0;
                        const int y = runs[k].y;
                        for (int x = runs[k].x0; x < runs[k].x1; ++x) {
                            for (int i = s.from(x, y), i1 = s.to(x, y); i < i1; ++i, ++n) {
                                tc.sampler.start_pixel_sample({x, y}, i);
                                trace(tc, sp, x, y, out);
                            }
                        }
                        tc.arena.reset();
                        progress.add(n);
                    },
                    apply);
            },
            [&](const AdaptiveSchedule& s) {
                return with_splats(film.resolve(), splat_film, double(s.taken()) / double(pixels));
            });
        for (auto& tc : contexts) r.rays += tc.rays;
        r.nonfinite_samples = nonfinite;
        record_adaptive(schedule, r);
        per_pixel = double(r.samples) / double(pixels);
    } else {
        int passes = run_chunked_schedule<ChunkOutput>(
            options, pixels, arena, progress,
            [&](ChunkOutput& out, int s, std::size_t p0, std::size_t p1) {
                ThreadContext& tc = contexts.local();
                Subpaths& sp = storage.local();
                clear(out);
                for (std::size_t p = p0; p < p1; ++p) {
                    int x = int(p % std::size_t(w)), y = int(p / std::size_t(w));
                    tc.sampler.start_pixel_sample({x, y}, s);
                    trace(tc, sp, x, y, out);
                }
                tc.arena.reset();
            },
            apply, [&](int k) { return with_splats(film.resolve(), splat_film, k); });
        for (auto& tc : contexts) r.rays += tc.rays;
        r.nonfinite_samples = nonfinite;
        r.spp = sum_over_group(options, passes, film.accumulators(), r);
        if (options.group) options.group->sum(splat_film.accumulators(), false);
        r.samples = pixels * std::uint64_t(r.spp);
        per_pixel = r.spp;
    }
    r.seconds = progress.elapsed_seconds();
    r.image = with_splats(film.resolve(), splat_film, per_pixel);
    // pbrt-v4's names: bdpt_d<depth>_s<s>_t<t>.exr for t >= 1, less s = 1, t = 1.
    for (int depth = 0; visualize && depth <= max_depth; ++depth)
        for (int s = 0; s <= depth + 2; ++s) {
            int t = depth + 2 - s;
            if (t == 0 || (s == 1 && t == 1)) continue;
            SplatFilm& f = strategy_films[std::size_t(strategy_index(s, t))];
            if (options.group) options.group->sum(f.accumulators(), false);
            r.extra_images.push_back(
                {fmt::format("bdpt_d{:02}_s{:02}_t{:02}.exr", depth, s, t), f.resolve(per_pixel)});
        }
    r.threads = threads;
    return r;
}

} // namespace illum
