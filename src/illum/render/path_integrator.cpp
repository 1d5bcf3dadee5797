#include "illum/render/path_integrator.h"

#include "illum/light/light.h"
#include "illum/render/texture_footprint.h"

namespace illum {

Radiance3 PathIntegrator::radiance(Ray ray, ThreadContext& tc) const {
    Radiance3 l;
    SampledSpectrum beta(1.0f); // path throughput
    float eta_scale = 1;        // radiance scaling by refraction, undone for Russian roulette
    bool specular_bounce = false;
    SolidAnglePdf prev_bsdf_pdf; // of the BSDF sample that made `ray`
    // A stochastic (layered) BSDF's sample carries no usable density: MIS weighs it with pdf() instead,
    // evaluated only when the ray finds emission (a pdf() costs a random walk).
    BSDF prev_bsdf;
    Vector3f prev_wo, prev_wi;
    auto bsdf_pdf_for_mis = [&] {
        if (prev_bsdf) {
            prev_bsdf_pdf = prev_bsdf.pdf(prev_wo, prev_wi);
            prev_bsdf = BSDF();
        }
        return prev_bsdf_pdf;
    };
    LightSampleContext prev_ctx;
    Sampler& sampler = tc.sampler;
    RayDifferentials rd = tc.path_differentials(); // valid only in scenes with filtered textures

    for (int depth = 0;;) {
        SurfaceHit hit;
        if (!intersect(ray, &hit, tc)) {
            for (const Light* env : scene_.infinite_lights) {
                Radiance3 le = env->le(ray, tc.lambda);
                if (le.is_black()) continue;
                if (depth == 0 || specular_bounce) {
                    l += le * beta;
                } else {
                    // Next-event estimation's density for this direction: pick the light, then sample it.
                    SolidAnglePdf p_light = scene_.direct_light_sampler.pmf(prev_ctx, env) *
                                            env->pdf_li(prev_ctx, ray.d, nullptr);
                    l += le * beta * power_heuristic(bsdf_pdf_for_mis(), p_light);
                }
            }
            break;
        }

        if (hit.area_light) {
            Radiance3 le = hit.area_light->radiance(hit, hit.wo, tc.lambda);
            if (!le.is_black()) {
                if (depth == 0 || specular_bounce) {
                    l += le * beta;
                } else {
                    SolidAnglePdf p_light = scene_.direct_light_sampler.pmf(prev_ctx, hit.area_light) *
                                            hit.area_light->pdf_li(prev_ctx, ray.d, &hit);
                    l += le * beta * power_heuristic(bsdf_pdf_for_mis(), p_light);
                }
            }
        }

        prev_bsdf = BSDF();
        tc.arena.reset(); // the previous vertex's BSDF is no longer needed
        if (needs_footprint(hit, rd)) [[unlikely]]
            compute_footprint(hit, rd, scene_, sampler.samples_per_pixel());
        BSDF bsdf = surface_bsdf(hit, tc.lambda, tc.arena);
        if (!bsdf) {
            // A pure interface (no material): the path continues straight through, no scattering event. Like
            // a specular bounce, emission found beyond it is counted in full: next-event estimation from the
            // previous vertex was blocked by the interface, so it did not find that light.
            specular_bounce = true;
            ray = hit.spawn_ray(ray.d);
            if (rd.valid) rd.advance(hit.t);
            continue;
        }
        if (bsdf.flags() == kNone) break; // a black surface scatters nothing
        if (max_depth_ >= 0 && depth >= max_depth_) break;
        ++depth;

        Vector3f wo = hit.wo;
        LightSampleContext ctx(hit);

        // Next-event estimation: one light picked by the light sampler for this point (a specular surface
        // takes its dimensions without computing them).
        const bool nee = bsdf.is_non_specular();
        float u_light = sampler.get_1d_if(nee);
        Point2f u_li = sampler.get_2d_if(nee);
        if (nee) {
            float pmf = 0;
            if (const Light* light = scene_.direct_light_sampler.sample(ctx, u_light, &pmf);
                light && pmf > 0) {
                if (auto ls = light->sample_li(ctx, u_li, tc.lambda)) {
                    Bsdf3 f = bsdf.f(wo, ls->wi);
                    float cos_i = abs_dot(ls->wi, hit.ns);
                    if (!f.is_black() && cos_i > 0 && unoccluded(hit, *ls, tc)) {
                        Radiance3 contrib = reflected(f, ls->biradiance, cos_i) * beta;
                        if (is_delta(light->type())) {
                            l += contrib / pmf;
                        } else {
                            SolidAnglePdf p_bsdf = bsdf.pdf(wo, ls->wi);
                            l += contrib * (power_heuristic(pmf * ls->pdf, p_bsdf) / pmf);
                        }
                    }
                }
            }
        }

        // Continue the path by sampling the BSDF.
        float u_lobe = sampler.get_1d_if(bsdf.reads_lobe_sample());
        Point2f u_dir = sampler.get_2d();
        auto bs = bsdf.sample(wo, u_lobe, u_dir);
        if (!bs) break;
        beta *= throughput_weight(bs->f, abs_dot(bs->wi, hit.ns), bs->pdf); // β f |cos θ| / p
        specular_bounce = bs->is_specular();
        prev_bsdf_pdf = bs->pdf;
        if (bs->pdf_is_proportional && !specular_bounce) {
            // A stochastic (layered) BSDF: its sample's pdf is not the density that pdf() returns, but MIS
            // stays unbiased as long as both strategies weigh with the same functions, so a light hit by
            // this sample is weighed with pdf() as next-event estimation is. (Weighing it 0 while
            // next-event estimation weighs by pdf() loses energy.) A delta sample (the coat's mirror
            // reflection) keeps full weight: next-event estimation cannot produce it.
            prev_bsdf = bsdf;
            prev_wo = wo;
            prev_wi = bs->wi;
        }
        if (bs->is_transmission()) eta_scale *= bs->eta * bs->eta;
        prev_ctx = ctx;
        ray = hit.spawn_ray(bs->wi);
        if (rd.valid) [[unlikely]]
            rd = continue_differentials(hit, rd, *bs);

        if (!beta.is_finite() || beta.is_black()) break;
        // Russian roulette after the first bounces: continue with probability min(1, max β·η²).
        float rr_beta = beta.max_component() * eta_scale;
        const bool roulette = rr_beta < 1 && depth > 1;
        float u_rr = sampler.get_1d_if(roulette);
        if (roulette) {
            float q = std::max(0.0f, 1 - rr_beta);
            if (u_rr < q) break;
            beta /= 1 - q;
        }
    }
    return l;
}

} // namespace illum
