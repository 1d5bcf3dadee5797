#include "illum/render/volpath_integrator.h"

#include <algorithm>

#include "illum/bsdf/material.h"
#include "illum/light/light.h"
#include "illum/medium/equiangular.h"
#include "illum/medium/medium.h"
#include "illum/medium/sample_majorant.h"
#include "illum/render/direct_view_mis.h"
#include "illum/render/shadow_transmittance.h"
#include "illum/render/texture_footprint.h"

namespace illum {

namespace {

// Surfaces without material a path may cross (a guard against a degenerate scene of nested interfaces).
constexpr int kMaxCrossings = 1024;

} // namespace

bool VolPathIntegrator::needed(const Scene& scene) {
    if (!scene.media.empty()) return true;
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const std::unique_ptr<Material>& m) { return m->interior() != nullptr; });
}

bool VolPathIntegrator::has_entry_media(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const std::unique_ptr<Material>& m) {
                           return m->interior() && m->interior()->evaluated_at_entry();
                       });
}

SampledSpectrum VolPathIntegrator::sample_light(const Vertex& v, PathState& path, ThreadContext& tc) const {
    Sampler& sampler = tc.sampler;
    float u_light = sampler.get_1d();
    Point2f u_li = sampler.get_2d();
    LightSampleContext ctx = v.hit ? LightSampleContext(*v.hit) : LightSampleContext(v.p, {}, {}, path.time);
    float pmf = 0;
    const Light* light = pick_light(ctx, u_light, &pmf);
    if (!light || pmf <= 0) return {};
    std::optional<LightLiSample> ls = light->sample_li(ctx, u_li, tc.lambda);
    if (!ls || ls->biradiance.s.is_black()) return {};

    // The scattering's value f |cos θ| (surface) or p (medium) and its density for the light's direction.
    SampledSpectrum f_hat;
    float scatter_pdf = 0;
    Ray shadow;
    if (v.hit) {
        Bsdf3 f = v.bsdf->f(v.hit->wo, ls->wi);
        f_hat = f.s * abs_dot(ls->wi, v.hit->ns);
        if (f_hat.is_black()) return {};
        scatter_pdf = v.bsdf->pdf(v.hit->wo, ls->wi).value;
        const SurfaceHit& h = *v.hit;
        if (ls->at_infinity)
            shadow = h.spawn_ray(ls->wi);
        else if (ls->n_light == Normal3f{})
            shadow = h.spawn_ray_to(ls->p_light);
        else {
            shadow = spawn_ray_to(h.p, h.p_error, h.n, ls->p_light, ls->p_light_error, ls->n_light);
            shadow.medium = h.medium_for(ls->p_light - h.p);
        }
    } else {
        float p = v.phase.p(dot(v.travel, ls->wi));
        f_hat = SampledSpectrum(p);
        scatter_pdf = p;
        if (ls->at_infinity)
            shadow = Ray{v.p, ls->wi, kInfinity, path.time, v.medium};
        else if (ls->n_light == Normal3f{})
            shadow = Ray{v.p, ls->p_light - v.p, 1 - 1e-4f, path.time, v.medium};
        else {
            Point3f target =
                offset_ray_origin(ls->p_light, ls->p_light_error, ls->n_light, v.p - ls->p_light);
            shadow = Ray{v.p, target - v.p, 1 - 1e-4f, path.time, v.medium};
        }
    }

    shadow.time = path.time;
    // Into a textured subsurface shape from its boundary: evaluated here, unless the path is inside.
    if (entry_media_ && v.hit) [[unlikely]]
        shadow.medium = path.enter(shadow.medium, *v.hit, tc.lambda, 1);
    SampledSpectrum r_u_t(1.0f), r_l_t(1.0f);
    ShadowTarget target{ls->p_light, ls->p_light_error, ls->n_light, ls->at_infinity, ls->wi};
    SampledSpectrum t_ray = shadow_transmittance(scene_, shadow, target, path.channel, path.rng, tc.lambda,
                                                 &r_u_t, &r_l_t, &tc.rays, &path.media);
    if (t_ray.is_black()) return {};

    // Contribution β f T L / avg(r_l + r_u) with r_l = r_p r_l,t p_light and r_u = r_p r_u,t p_scatter,
    // written with the light's biradiance L / p_light (which a delta light gives directly).
    SampledSpectrum r_l = path.r_u * r_l_t;
    if (v.segment && light->position()) {
        // This scattering point could also have come from equiangular sampling towards the light: the
        // balance heuristic over free flight (density σ_s T per channel) and it (p_eq), in terms of the
        // path's densities at the segment's origin: r_u0 (p_ff + p_eq) / p_ff[channel].
        const Equiangular* eq = v.segment->towards(*light);
        float p_eq = eq ? eq->pdf(v.t) : 0.0f;
        r_l += r_l_t * v.segment->r_u0 * (p_eq / v.p_free_flight[path.channel]);
    }
    SampledSpectrum r_u(0.0f);
    if (!is_delta(light->type())) r_u = path.r_u * r_u_t * (scatter_pdf / (pmf * ls->pdf.value));
    float denom = (r_l + r_u).average();
    if (!(denom > 0)) return {};
    return path.beta * f_hat * t_ray * ls->biradiance.s / (pmf * denom);
}

SampledSpectrum VolPathIntegrator::sample_equiangular(Segment& seg, const Medium& medium,
                                                      SampledSpectrum beta, PathState& path,
                                                      ThreadContext& tc) const {
    Sampler& sampler = tc.sampler;
    float u_light = sampler.get_1d(), u_t = sampler.get_1d();
    Point2f u_li = sampler.get_2d();
    float pmf = 0;
    const Light* light = scene_.light_sampler.sample(u_light, &pmf);
    if (!light || pmf <= 0) return {};
    if (!light->position()) return {}; // free flight alone samples the other lights' single scattering
    const Equiangular* eq = seg.towards(*light);
    if (!eq) return {};
    float p_eq = 0;
    float t = eq->sample(u_t, &p_eq);
    if (!(p_eq > 0)) return {};
    Point3f x = seg.o + seg.d * t;
    const MediumProperties mp =
        path.media.get(medium, tc.lambda); // a copy: the shadow ray may refill the cache
    if (mp.sigma_s.is_black()) return {};
    std::optional<LightLiSample> ls =
        light->sample_li(LightSampleContext(x, {}, {}, path.time), u_li, tc.lambda);
    if (!ls || ls->biradiance.s.is_black()) return {};
    SampledSpectrum t_cam = exp(-(mp.sigma_a + mp.sigma_s) * t); // exact: the medium is homogeneous
    SampledSpectrum p_free_flight = mp.sigma_s * t_cam;
    float phase = mp.phase.p(dot(seg.d, ls->wi));
    Ray shadow{x, ls->p_light - x, 1 - 1e-4f, path.time, &medium};
    SampledSpectrum r_u_t(1.0f), r_l_t(1.0f);
    ShadowTarget target{ls->p_light, ls->p_light_error, ls->n_light, false, ls->wi};
    SampledSpectrum t_ray = shadow_transmittance(scene_, shadow, target, path.channel, path.rng, tc.lambda,
                                                 &r_u_t, &r_l_t, &tc.rays, &path.media);
    if (t_ray.is_black()) return {};
    // The balance heuristic with free flight (sample_light): F / avg(r_u0 r_l,t (p_ff + p_eq)).
    float denom = (seg.r_u0 * r_l_t * (p_free_flight + SampledSpectrum(p_eq))).average();
    if (!(denom > 0)) return {};
    return beta * t_cam * mp.sigma_s * (phase / (pmf * denom)) * t_ray * ls->biradiance.s;
}

Radiance3 VolPathIntegrator::estimate(const Ray& camera_ray, ThreadContext& tc) const {
    Sampler& sampler = tc.sampler;
    Ray ray = camera_ray;
    ray.medium = scene_.camera_medium;
    PathState path;
    path.time = camera_ray.time;
    path.channel = std::min(kSpectrumSamples - 1, int(sampler.get_1d() * kSpectrumSamples));
    {
        float a = sampler.get_1d(), b = sampler.get_1d();
        path.rng.set_sequence(hash(std::uint32_t(a * 0x1p32f), std::uint32_t(b * 0x1p32f)));
    }
    const int ch = path.channel;
    // Path space is split with light tracing only where it can splat: camera samples on the film (a filter
    // wider than half a pixel puts border pixels' samples outside it).
    // (Asked only when a path finds an area light, which most do not.)
    int on_film = -1;
    auto split = [&] {
        if (on_film < 0) on_film = scene_.camera_pdf_we(camera_ray).dir.value > 0 ? 1 : 0;
        return on_film == 1;
    };
    SampledSpectrum& beta = path.beta;
    SampledSpectrum& r_u = path.r_u;
    SampledSpectrum& r_l = path.r_l;
    SampledSpectrum l(0.0f);
    bool specular_bounce = false;
    bool first_vertex_non_specular = false; // the first scattering event was not specular
    float eta_scale = 1;
    int depth = 0;
    LightSampleContext prev_ctx;
    RayDifferentials rd = tc.path_differentials(); // valid only in scenes with filtered textures
    const bool entry_media = entry_media_;

    // Emission found by the unidirectional technique, weighed against light sampling from prev_ctx.
    auto add_emission = [&](SampledSpectrum le, const Light* light, const SurfaceHit* hit) {
        if (le.is_black()) return;
        // A caustic (specular bounce before the light, non-specular first vertex) is light tracing's, for
        // film positions light tracing can splat to.
        if (caustics_by_light_tracing_ && hit && specular_bounce && depth > 0 && first_vertex_non_specular &&
            split())
            return;
        if (depth == 0 && caustics_by_light_tracing_ && hit && split()) {
            // A light seen directly: weighed against light tracing's view of it (volpath_caustics.h).
            float w = direct_view_weight(scene_, *light, hit->p, hit->n, camera_ray.o, hit->time,
                                         /*for_camera=*/true);
            l += beta * le * (w / r_u.average());
        } else if (depth == 0 || specular_bounce) {
            l += beta * le / r_u.average();
        } else {
            float p_light = pick_light_pmf(prev_ctx, light) * light->pdf_li(prev_ctx, ray.d, hit).value;
            l += beta * le / (r_u + r_l * p_light).average();
        }
    };

    for (int crossings = 0; crossings < kMaxCrossings;) {
        // The surface's data is computed only once the path reaches it (a collision in the medium may come
        // first).
        Accelerator::Found found_hit;
        bool found = find(ray, &found_hit, tc);
        if (ray.medium) {
            bool scattered = false, terminated = false;
            float tmax = found ? found_hit.t() : kInfinity;
            const Medium* medium = ray.medium;
            // Equiangular single scattering towards point and spot lights on a homogeneous stretch.
            Segment seg;
            const bool equiangular =
                point_lights_ && medium->is_homogeneous() && (max_depth_ < 0 || depth < max_depth_);
            if (equiangular) {
                float len = length(ray.d);
                seg.o = ray.o;
                seg.d = ray.d / len;
                seg.t_end = found ? found_hit.t() * len : kInfinity;
                seg.r_u0 = r_u;
                l += sample_equiangular(seg, *medium, beta, path, tc);
            }
            SampledSpectrum t_maj = sample_t_maj(
                ray, tmax, sampler.get_1d(), path.rng, tc.lambda, ch, &path.media,
                [&](Point3f p, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum t_m) {
                    // The medium's emission σ_a Le, collected at every tentative collision.
                    if ((max_depth_ < 0 || depth < max_depth_) && !mp.le.is_black()) {
                        float pdf = sigma_maj[ch] * t_m[ch];
                        SampledSpectrum r_e = r_u * sigma_maj * t_m / pdf;
                        float avg = r_e.average();
                        if (avg > 0) l += beta * t_m / pdf * mp.sigma_a * mp.le / avg;
                    }
                    MediumEvent event = choose_medium_event(mp, sigma_maj, ch, path.rng.uniform_float(),
                                                            medium->is_homogeneous());
                    if (event == MediumEvent::Absorb) {
                        terminated = true;
                        return false;
                    }
                    if (event == MediumEvent::Scatter) {
                        if (max_depth_ >= 0 && depth >= max_depth_) {
                            terminated = true;
                            return false;
                        }
                        if (++depth == 1) first_vertex_non_specular = true;
                        float pdf = t_m[ch] * mp.sigma_s[ch];
                        beta *= t_m * mp.sigma_s / pdf;
                        r_u *= t_m * mp.sigma_s / pdf;
                        if (beta.is_black() || r_u.is_black()) {
                            terminated = true;
                            return false;
                        }
                        Vertex v;
                        v.p = p;
                        v.medium = medium;
                        v.travel = ray.d / length(ray.d);
                        v.phase = mp.phase;
                        if (equiangular) {
                            v.segment = &seg;
                            v.t = distance(seg.o, p);
                            v.p_free_flight = t_m * mp.sigma_s;
                        }
                        l += sample_light(v, path, tc);
                        float phase_pdf = 0;
                        Vector3f wi = mp.phase.sample(v.travel, sampler.get_2d(), &phase_pdf);
                        if (!(phase_pdf > 0)) {
                            terminated = true;
                            return false;
                        }
                        // β *= p / pdf = 1 for the exactly sampled Henyey-Greenstein.
                        r_l = r_u / phase_pdf;
                        prev_ctx = LightSampleContext(p, {}, {}, ray.time);
                        ray = Ray{p, wi, kInfinity, ray.time, medium};
                        rd.valid = false;
                        specular_bounce = false;
                        scattered = true;
                        return false;
                    }
                    // A null collision: the walk goes on.
                    SampledSpectrum sigma_n = null_coefficient(mp, sigma_maj);
                    float pdf = t_m[ch] * sigma_n[ch];
                    if (pdf == 0) {
                        beta = SampledSpectrum(0.0f);
                        return false;
                    }
                    beta *= t_m * sigma_n / pdf;
                    r_u *= t_m * sigma_n / pdf;
                    r_l *= t_m * sigma_maj / pdf;
                    return !beta.is_black() && !r_u.is_black();
                });
            if (terminated || beta.is_black() || r_u.is_black() || !beta.is_finite()) break;
            if (scattered) continue;
            SampledSpectrum rel = relative_to_channel(t_maj, ch);
            beta *= rel;
            r_u *= rel;
            // Light sampling crossed a homogeneous medium exactly (density 1), a grid by ratio tracking.
            if (medium->is_homogeneous())
                r_l *= t_maj[ch] > 0 ? 1 / t_maj[ch] : 0.0f;
            else
                r_l *= rel;
            if (beta.is_black()) break;
        }

        SurfaceHit hit;
        if (found) found = scene_.complete(found_hit, ray, &hit);
        if (!found) {
            for (const Light* env : scene_.infinite_lights)
                add_emission(env->le(ray, tc.lambda).s, env, nullptr);
            break;
        }
        if (hit.area_light)
            add_emission(hit.area_light->radiance(hit, hit.wo, tc.lambda).s, hit.area_light, &hit);

        tc.arena.reset();
        if (needs_footprint(hit, rd)) [[unlikely]]
            compute_footprint(hit, rd, scene_, sampler.samples_per_pixel());
        BSDF bsdf = surface_bsdf(hit, tc.lambda, tc.arena);
        if (!bsdf) {
            // A boundary between media with no surface: the path goes on unchanged.
            ray = hit.spawn_ray(ray.d);
            if (rd.valid) rd.advance(hit.t);
            ++crossings;
            continue;
        }
        if (bsdf.flags() == kNone) break;
        if (max_depth_ >= 0 && depth >= max_depth_) break;
        ++depth;

        if (bsdf.is_non_specular()) {
            Vertex v;
            v.hit = &hit;
            v.bsdf = &bsdf;
            l += sample_light(v, path, tc);
        }
        prev_ctx = LightSampleContext(hit);

        float u_lobe = sampler.get_1d_if(bsdf.reads_lobe_sample());
        Point2f u_dir = sampler.get_2d();
        auto bs = bsdf.sample(hit.wo, u_lobe, u_dir);
        if (!bs) break;
        beta *= throughput_weight(bs->f, abs_dot(bs->wi, hit.ns), bs->pdf);
        float pdf_for_mis = bs->pdf_is_proportional ? bsdf.pdf(hit.wo, bs->wi).value : bs->pdf.value;
        r_l = pdf_for_mis > 0 ? r_u / pdf_for_mis : SampledSpectrum(0.0f);
        specular_bounce = bs->is_specular();
        if (depth == 1) first_vertex_non_specular = !specular_bounce;
        if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
        ray = hit.spawn_ray(bs->wi);
        if (entry_media) [[unlikely]]
            ray.medium = path.enter(ray.medium, hit, tc.lambda, 0);
        if (rd.valid) [[unlikely]]
            rd = continue_differentials(hit, rd, *bs);

        if (!beta.is_finite() || beta.is_black()) break;
        // Russian roulette on the MIS-weighted throughput, after the first bounces.
        float rr_beta = (beta * eta_scale / r_u.average()).max_component();
        const bool roulette = rr_beta < 1 && depth > 1;
        float u_rr = sampler.get_1d_if(roulette);
        if (roulette) {
            float q = std::max(0.0f, 1 - rr_beta);
            if (u_rr < q) break;
            beta /= 1 - q;
        }
    }
    return Radiance3(l);
}

} // namespace illum
