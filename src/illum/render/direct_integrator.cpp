#include "illum/render/direct_integrator.h"
#include "illum/render/texture_footprint.h"

namespace illum {

Radiance3 DirectIntegrator::reflected_from(const Light& light, const SurfaceHit& hit, const BSDF& bsdf,
                                           ThreadContext& tc) const {
    Radiance3 l;
    LightSampleContext ctx(hit);
    Point2f u_light = tc.sampler.get_2d();
    float u_lobe = tc.sampler.get_1d_if(bsdf.reads_lobe_sample());
    Point2f u_bsdf = tc.sampler.get_2d();

    // Light sampling.
    if (auto ls = light.sample_li(ctx, u_light, tc.lambda)) {
        Bsdf3 f = bsdf.f(hit.wo, ls->wi);
        float cos_i = abs_dot(ls->wi, hit.ns);
        if (!f.is_black() && cos_i > 0 && unoccluded(hit, *ls, tc)) {
            Radiance3 contrib = reflected(f, ls->biradiance, cos_i);
            if (is_delta(light.type())) return contrib; // exact: no integral, no BSDF sample
            l += contrib * power_heuristic(ls->pdf, bsdf.pdf(hit.wo, ls->wi));
        }
    }
    if (is_delta(light.type())) return l;

    // BSDF sampling: does the sampled direction reach this light? A delta lobe (the mirror reflection of a
    // coat over a diffuse base) is counted in full: light sampling cannot produce its direction.
    auto bs = bsdf.sample(hit.wo, u_lobe, u_bsdf);
    if (!bs) return l;
    Ray ray = hit.spawn_ray(bs->wi);
    SurfaceHit lhit;
    Radiance3 le;
    SolidAnglePdf p_light;
    if (intersect(ray, &lhit, tc)) {
        if (lhit.area_light != &light) return l;
        le = light.radiance(lhit, lhit.wo, tc.lambda);
        if (!bs->is_specular()) p_light = light.pdf_li(ctx, bs->wi, &lhit);
    } else if (light.type() == LightType::Infinite) {
        le = light.le(ray, tc.lambda);
        if (!bs->is_specular()) p_light = light.pdf_li(ctx, bs->wi, nullptr);
    }
    if (le.is_black()) return l;
    // A stochastic (layered) BSDF's sample pdf is not the density pdf() gives; both strategies must weigh
    // with the same function for the weights to sum to one, so use pdf() here as light sampling does.
    SolidAnglePdf p_bsdf = bs->pdf_is_proportional ? bsdf.pdf(hit.wo, bs->wi) : bs->pdf;
    float w = bs->is_specular() ? 1.0f : power_heuristic(p_bsdf, p_light);
    // The MIS-weighted BSDF-sampling estimate: L_e · f |cos θ| w / p.
    l += le * throughput_weight(bs->f, abs_dot(bs->wi, hit.ns) * w, bs->pdf);
    return l;
}

Radiance3 DirectIntegrator::radiance(Ray ray, ThreadContext& tc) const {
    Radiance3 l;
    SampledSpectrum beta(1.0f);
    for (int depth = 0;;) {
        tc.arena.reset();
        SurfaceHit hit;
        if (!intersect(ray, &hit, tc)) {
            for (const Light* env : scene_.infinite_lights) l += env->le(ray, tc.lambda) * beta;
            break;
        }
        if (hit.area_light) l += hit.area_light->radiance(hit, hit.wo, tc.lambda) * beta;
        footprint_from_camera(hit, scene_, tc.sampler.samples_per_pixel());
        BSDF bsdf = surface_bsdf(hit, tc.lambda, tc.arena);
        if (!bsdf) {
            ray = hit.spawn_ray(ray.d);
            continue;
        }
        if (bsdf.flags() == kNone) break;
        if (bsdf.is_non_specular()) {
            Radiance3 direct;
            for (const auto& light : scene_.lights) direct += reflected_from(*light, hit, bsdf, tc);
            l += direct * beta;
            break;
        }
        // A specular surface: follow the reflection/refraction.
        if (max_depth_ >= 0 && depth >= max_depth_) break;
        ++depth;
        const float u_lobe =
            tc.sampler.get_1d_if(bsdf.reads_lobe_sample()); // before u_dir (a call's arguments have no order)
        const Point2f u_dir = tc.sampler.get_2d();
        auto bs = bsdf.sample(hit.wo, u_lobe, u_dir);
        if (!bs) break;
        beta *= throughput_weight(bs->f, abs_dot(bs->wi, hit.ns), bs->pdf);
        ray = hit.spawn_ray(bs->wi);
    }
    return l;
}

} // namespace illum
