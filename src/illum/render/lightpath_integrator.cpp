#include "illum/render/lightpath_integrator.h"

#include <algorithm>
#include <fmt/format.h>
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_group.h>
#include <optional>
#include <thread>

#include "illum/light/light.h"
#include "illum/medium/entry_medium.h"
#include "illum/medium/sample_majorant.h"
#include "illum/render/chunked_schedule.h"
#include "illum/render/direct_view_mis.h"
#include "illum/render/path_vertex.h"
#include "illum/render/render_arena.h"
#include "illum/render/shadow_transmittance.h"
#include "illum/render/texture_footprint.h"
#include "illum/util/error.h"
#include "illum/util/in_place.h"
#include "illum/util/progress.h"

namespace illum {

LightPathIntegrator::LightPathIntegrator(const Scene& scene, int max_depth, bool caustics_only)
    : WholeImageIntegrator(scene), max_depth_(max_depth), caustics_only_(caustics_only) {
    if (!scene.camera || !scene.camera->has_importance())
        throw Error(
            scene.camera_loc,
            fmt::format(
                "integrator \"lightpath\" cannot use camera \"{}\": it needs a perspective camera or an "
                "orthographic one without a lens (the realistic and spherical cameras and a "
                "thin-lens orthographic one have no importance function)",
                scene.camera_type));
}

int LightPathIntegrator::trace_particle(ThreadContext& tc, bool spectral,
                                        LineAlignedVector<Splat>& out) const {
    Sampler& sampler = tc.sampler;
    int dropped = 0;
    auto splat = [&](Point2f p_raster, const Radiance3& l) {
        if (!l.is_finite() || l.has_negative()) {
            ++dropped;
            return;
        }
        out.push_back({p_raster, scene_.sensor.to_film(l, tc.lambda)});
    };

    assign_in_place(tc.lambda, [&] { return scene_.sample_wavelengths(spectral, sampler); });
    float pmf = 0;
    const Light* light = scene_.light_sampler.sample(sampler.get_1d(), &pmf);
    if (!light || !(pmf > 0)) return dropped;
    // Caustics only: the environment's caustics stay with the camera paths (their light end is not traced).
    if (caustics_only_ && light->type() == LightType::Infinite) return dropped;
    Point2f u_pos = sampler.get_2d(), u_dir = sampler.get_2d();
    // Motion blur: the particle's time, drawn in the shutter interval as a camera sample's is (a moving
    // light emits it from where it is then).
    const float time = scene_.has_motion ? scene_.sample_time(sampler.get_1d()) : 0.0f;
    std::optional<LightLeSample> les = light->sample_le_at(time, u_pos, u_dir, tc.lambda);
    if (!les || !(les->pdf_pos.value > 0) || !(les->pdf_dir.value > 0) || les->flux.is_black())
        return dropped;
    // Media: collisions are sampled in one channel, chosen per particle, and every splat is divided by the
    // average over the channels of the path's density relative to it (r_u; volpath_integrator.h).
    const int ch = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
    PCG32 rng;
    {
        float a = sampler.get_1d(), b = sampler.get_1d();
        rng.set_sequence(hash(std::uint32_t(a * 0x1p32f), std::uint32_t(b * 0x1p32f)));
    }
    SampledSpectrum r_u(1.0f);

    // A connection from `from` (in `medium`, leaving a surface when `hit` is given) to the lens point of
    // cs: the media's transmittance and its light-sampling density ratio r_l (a camera connection is the
    // only technique, so the splat divides by the path's average density ratio r_u r_l).
    auto connect = [&](const SurfaceHit* hit, Point3f from, const Medium* medium, const CameraWiSample& cs,
                       SampledSpectrum value) {
        Ray shadow =
            hit ? hit->spawn_ray_to(cs.p_lens) : Ray{from, cs.p_lens - from, 1 - 1e-4f, time, medium};
        SampledSpectrum r_u_t(1.0f), r_l_t(1.0f);
        SampledSpectrum t = shadow_transmittance(scene_, shadow, ShadowTarget{cs.p_lens, {}, {}, false, {}},
                                                 ch, rng, tc.lambda, &r_u_t, &r_l_t, &tc.rays);
        if (t.is_black()) return;
        float avg = (r_u * r_l_t).average();
        if (avg > 0) splat(cs.p_raster, Radiance3(value * t * ((cs.we / cs.pdf).value / avg)));
    };

    // The light's own point seen by the camera (s = 1, t = 1; Veach 1997 §10.2): the point y on the light
    // came with area density p_A(y) = pdf_pos, the lens point with p_ω at y, so
    //   L = L_e(y → lens) |cos θ_y| W_e / (p_light p_A(y) p_ω).
    // (pbrt-v4 divides by the light's Pdf_Li from the lens instead of p_A(y).) Delta-position lights have
    // no area to be seen.
    Point2f u_cam = sampler.get_2d_if(scene_.camera->uses_lens_sample());
    if (light->type() == LightType::Area) {
        if (auto cs = scene_.camera_sample_wi(les->p_surface, u_cam, time)) {
            SurfaceHit y;
            y.p = les->p_surface;
            y.n = les->n;
            y.ns = les->n;
            y.time = time;
            Radiance3 le = light->radiance(y, cs->wi, tc.lambda);
            float cos_y = std::abs(dot(Vector3f(les->n), cs->wi));
            if (!le.is_black() && cos_y > 0) {
                // From the light towards the lens, in the medium on the lens's side of the emitter; the
                // ray stops 1e-4 of the way short of the lens.
                Point3f o = offset_ray_origin(les->p_surface, les->p_error, les->n, cs->wi);
                // Beside volpath, weighed against its camera rays that hit the light (direct_view_mis.h).
                float w = caustics_only_
                              ? direct_view_weight(scene_, *light, les->p_surface, les->n, cs->p_lens, time,
                                                   /*for_camera=*/false)
                              : 1.0f;
                connect(nullptr, o, light->medium_towards(cs->wi, les->n), *cs,
                        le.s * (w * cos_y / pmf) / les->pdf_pos.value);
            }
        }
    }

    // The particle's throughput: its flux estimate over the light's selection probability, then
    // f |cos θ| / p per bounce (importance transport, with the adjoint's shading-normal factor) and, in
    // media, σ_s T / p per real collision.
    SampledSpectrum beta = (les->flux / pmf).s;
    const float beta0 = beta.max_component();
    Ray ray = les->ray;
    ray.time = time;
    ray.medium = light->medium_towards(ray.d, les->n);
    bool first_vertex = true; // caustics only: the first scattering must be specular
    // Into a textured subsurface shape: its medium evaluated where the particle enters (entry_medium.h).
    std::optional<EntryMedium> entry;
    auto enter = [&](const SurfaceHit& hit) {
        ray.medium =
            entered_medium(ray.medium, hit, tc.lambda, [&] { return entry ? &*entry : &entry.emplace(); });
    };
    for (int depth = 0, crossings = 0; (max_depth_ < 0 || depth < max_depth_) && crossings < 1024;) {
        SurfaceHit hit;
        bool found = intersect(ray, &hit, tc);
        if (ray.medium) {
            bool scattered = false, terminated = false;
            const Medium* medium = ray.medium;
            SampledSpectrum t_maj = sample_t_maj(
                ray, found ? hit.t : kInfinity, sampler.get_1d(), rng, tc.lambda, ch,
                [&](Point3f p, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum t_m) {
                    MediumEvent event =
                        choose_medium_event(mp, sigma_maj, ch, rng.uniform_float(), medium->is_homogeneous());
                    if (event == MediumEvent::Absorb) {
                        terminated = true;
                        return false;
                    }
                    if (event == MediumEvent::Scatter) {
                        // A medium vertex is not specular: with caustics only, a particle scattered first
                        // in a medium is the camera paths' to find.
                        if (caustics_only_ && first_vertex) {
                            terminated = true;
                            return false;
                        }
                        first_vertex = false;
                        float pdf = t_m[ch] * mp.sigma_s[ch];
                        beta *= t_m * mp.sigma_s / pdf;
                        r_u *= t_m * mp.sigma_s / pdf;
                        Vector3f travel = ray.d / length(ray.d);
                        Point2f u_lens = sampler.get_2d_if(scene_.camera->uses_lens_sample());
                        if (auto cs = scene_.camera_sample_wi(p, u_lens, time))
                            connect(nullptr, p, medium, *cs, beta * mp.phase.p(dot(travel, cs->wi)));
                        ++depth;
                        float phase_pdf = 0;
                        Vector3f wi = mp.phase.sample(travel, sampler.get_2d(), &phase_pdf);
                        if (!(phase_pdf > 0) || (max_depth_ >= 0 && depth >= max_depth_)) {
                            terminated = true;
                            return false;
                        }
                        ray = Ray{p, wi, kInfinity, ray.time, medium};
                        scattered = true;
                        return false;
                    }
                    SampledSpectrum sigma_n = null_coefficient(mp, sigma_maj);
                    float pdf = t_m[ch] * sigma_n[ch];
                    if (pdf == 0) {
                        terminated = true;
                        return false;
                    }
                    beta *= t_m * sigma_n / pdf;
                    r_u *= t_m * sigma_n / pdf;
                    return !beta.is_black();
                });
            if (terminated || beta.is_black() || !beta.is_finite()) break;
            if (scattered) continue;
            SampledSpectrum rel = relative_to_channel(t_maj, ch);
            beta *= rel;
            r_u *= rel;
            if (beta.is_black()) break;
        }
        if (!found) break;
        tc.arena.reset();
        footprint_from_camera(hit, scene_, tc.sampler.samples_per_pixel());
        BSDF bsdf = surface_bsdf(hit, tc.lambda, tc.arena);
        if (!bsdf) {
            ray = hit.spawn_ray(ray.d); // an interface without material: no vertex
            ++crossings;
            continue;
        }
        if (bsdf.flags() == kNone) break;
        Vector3f wo = hit.wo;

        // Connect to the camera (t = 1): L = β f*(ωo → ωc) |cos θc| W_e / p_ω (PBR 4th ed. §16.3.2).
        Point2f u_lens = sampler.get_2d_if(scene_.camera->uses_lens_sample());
        if (bsdf.is_non_specular() && !(caustics_only_ && first_vertex)) {
            if (auto cs = scene_.camera_sample_wi(hit.p, u_lens, time)) {
                Bsdf3 f = bsdf.f(wo, cs->wi, TransportMode::Importance);
                float cos_c =
                    std::abs(dot(cs->wi, Vector3f(hit.ns))) * shading_normal_adjoint(hit, wo, cs->wi);
                if (!f.is_black() && cos_c > 0) connect(&hit, hit.p, nullptr, *cs, beta * f.s * cos_c);
            }
        }

        // Scatter.
        float u_lobe = sampler.get_1d_if(bsdf.reads_lobe_sample());
        Point2f u_bsdf = sampler.get_2d();
        auto bs = bsdf.sample(wo, u_lobe, u_bsdf, TransportMode::Importance);
        if (!bs) break;
        if (caustics_only_ && first_vertex && !bs->is_specular()) break;
        first_vertex = false;
        float cos_i = std::abs(dot(bs->wi, Vector3f(hit.ns))) * shading_normal_adjoint(hit, wo, bs->wi);
        beta *= throughput_weight(bs->f, cos_i, bs->pdf);
        ray = hit.spawn_ray(bs->wi);
        enter(hit);
        ++depth;
        if (!beta.is_finite() || beta.is_black()) break;

        // Russian roulette (not in pbrt-v4's lightpath; unbiased): after two bounces continue with
        // probability min(1, max β / max β₀).
        float u_rr = sampler.get_1d();
        float rr = beta.max_component() / beta0;
        if (rr < 1 && depth > 1) {
            float q = std::max(0.0f, 1 - rr);
            if (u_rr < q) break;
            beta *= 1 / (1 - q);
        }
    }
    return dropped;
}

RenderResult LightPathIntegrator::render_image(const RenderOptions& options) const {
    const int w = scene_.width, h = scene_.height;
    const std::size_t pixels = std::size_t(w) * h;
    int threads = render_threads(options);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);

    const Sampler prototype = make_sampler(options, options.spp > 0 ? options.spp : 1, {w, h});
    tbb::enumerable_thread_specific<ThreadContext> contexts([&] { return ThreadContext(prototype); });
    SplatFilm film(w, h, *scene_.filter);
    const bool spectral = options.spectral;

    // One chunk's splats and the number of contributions dropped as non-finite.
    struct ChunkSplats {
        LineAlignedVector<Splat> splats; // written by one thread while others write theirs (line_aligned.h)
        int dropped = 0;
    };
    std::uint64_t nonfinite = 0;
    const bool timed = options.time_budget > 0;
    Progress progress("render",
                      timed ? 0 : pixels * std::uint64_t(sample_share(options.group).count(options.spp)),
                      "samples", options.quiet);
    int passes = run_chunked_schedule<ChunkSplats>(
        options, pixels, arena, progress,
        [&](ChunkSplats& out, int s, std::size_t p0, std::size_t p1) {
            ThreadContext& tc = contexts.local();
            out.splats.clear();
            out.dropped = 0;
            for (std::size_t p = p0; p < p1; ++p) {
                tc.sampler.start_pixel_sample({int(p % w), int(p / w)}, s);
                out.dropped += trace_particle(tc, spectral, out.splats);
            }
            tc.arena.reset();
        },
        [&](const ChunkSplats& out) {
            for (const Splat& sp : out.splats) film.add_splat(sp);
            nonfinite += std::uint64_t(out.dropped);
        },
        [&](int k) { return film.resolve(k); });

    RenderResult r;
    for (auto& tc : contexts) r.rays += tc.rays;
    r.nonfinite_samples = nonfinite;
    r.spp = sum_over_group(options, passes, film.accumulators(), r);
    r.seconds = progress.elapsed_seconds();
    r.image = film.resolve(r.spp);
    r.samples = pixels * std::uint64_t(r.spp);
    r.threads = threads;
    return r;
}

} // namespace illum
