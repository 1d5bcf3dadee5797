#include "illum/render/path_vertex.h"

#include <algorithm>
#include <optional>

#include "illum/bsdf/material.h"
#include "illum/medium/entry_medium.h"
#include "illum/medium/medium.h"
#include "illum/medium/sample_majorant.h"
#include "illum/render/shadow_transmittance.h"
#include "illum/render/texture_footprint.h"
#include "illum/util/in_place.h"

namespace illum {

namespace {

// Surfaces without material a walk may cross (a guard against a degenerate scene of nested interfaces).
constexpr int kMaxCrossings = 1024;

TransportMode other(TransportMode m) {
    return m == TransportMode::Radiance ? TransportMode::Importance : TransportMode::Radiance;
}

// The medium a subpath's ray leaving `hit` travels in (next = hit.medium_for(its direction)): a textured
// subsurface shape's medium is evaluated where this subpath enters it (entry_medium.h), in the thread's
// arena, which lives as long as the sample's subpaths.
const Medium* walk_into(const PathContext& ctx, const Medium* next, const SurfaceHit& hit) {
    return entered_medium(next, hit, ctx.tc.lambda, [&] { return ctx.tc.arena.make<EntryMedium>(); });
}

} // namespace

const Medium* PathVertex::medium_towards(Point3f q) const {
    switch (type) {
    case VertexType::Surface:
        return hit.medium_for(q - p);
    case VertexType::Light:
        return light ? light->medium_towards(q - p, ng) : nullptr;
    default:
        return medium;
    }
}

float shading_normal_adjoint(const SurfaceHit& hit, Vector3f wo, Vector3f wi) {
    if (hit.ns == hit.n) return 1;
    float num = std::abs(dot(wo, Vector3f(hit.ns))) * std::abs(dot(wi, Vector3f(hit.n)));
    float den = std::abs(dot(wo, Vector3f(hit.n))) * std::abs(dot(wi, Vector3f(hit.ns)));
    return den > 0 ? num / den : 0.0f;
}

float convert_density(const PathVertex& v, float pdf, const PathVertex& next) {
    if (next.is_infinite_light()) return pdf;
    Vector3f w = next.p - v.p;
    float d2 = length_squared(w);
    if (!(d2 > 0)) return 0;
    float inv_d2 = 1 / d2;
    if (next.on_surface()) pdf *= std::abs(dot(Vector3f(next.ng), w)) * std::sqrt(inv_d2);
    return pdf * inv_d2;
}

float infinite_light_density(const PathContext& ctx, Vector3f w) {
    float pdf = 0;
    for (const Light* l : ctx.scene.infinite_lights) {
        AreaPdf pos;
        SolidAnglePdf dir;
        l->pdf_le(Ray{Point3f{}, w}, {}, &pos, &dir);
        pdf += ctx.scene.light_sampler.pmf(l) * dir.value;
    }
    return pdf;
}

float pdf_light(const PathContext& ctx, const PathVertex& v, const PathVertex& next) {
    Vector3f w = next.p - v.p;
    float d2 = length_squared(w);
    if (!(d2 > 0)) return 0;
    float inv_d2 = 1 / d2;
    w = w * std::sqrt(inv_d2);
    float pdf = 0;
    if (v.is_infinite_light()) {
        // The photon starts on the disk of the scene's radius: its density per unit area at next is the
        // disk's (perpendicular to w) times the cosine there.
        pdf = disk_emission_pdf(ctx.scene_radius).value;
    } else {
        const Light* light = v.type == VertexType::Light ? v.light : v.hit.area_light;
        if (!light) return 0;
        AreaPdf pos;
        SolidAnglePdf dir;
        light->pdf_le(Ray{v.p, w, kInfinity, ctx.time}, v.ng, &pos, &dir);
        pdf = dir.value * inv_d2;
    }
    if (next.on_surface()) pdf *= std::abs(dot(Vector3f(next.ng), w));
    return pdf;
}

float pdf_light_origin(const PathContext& ctx, const PathVertex& v, const PathVertex& next) {
    Vector3f w = next.p - v.p;
    float d2 = length_squared(w);
    if (!(d2 > 0)) return 0;
    w = w / std::sqrt(d2);
    if (v.is_infinite_light()) return infinite_light_density(ctx, w);
    const Light* light = v.type == VertexType::Light ? v.light : v.hit.area_light;
    if (!light) return 0;
    AreaPdf pos;
    SolidAnglePdf dir;
    light->pdf_le(Ray{v.p, w, kInfinity, ctx.time}, v.ng, &pos, &dir);
    return ctx.scene.light_sampler.pmf(light) * pos.value;
}

Segment segment(Point3f a, Point3f b) {
    Vector3f w = b - a;
    float d2 = length_squared(w);
    if (!(d2 > 0)) return {};
    float inv_d2 = 1 / d2;
    return {w * std::sqrt(inv_d2), inv_d2};
}

float vertex_pdf(const PathContext& ctx, const PathVertex& v, Vector3f wp, Vector3f wn,
                 const PathVertex& next, float inv_d2) {
    if (v.type == VertexType::Light) return pdf_light(ctx, v, next);
    return vertex_pdf(ctx, v, wp, wn, density_target(next), inv_d2);
}

namespace {

// A solid-angle density at a vertex of the unit direction wn towards `next`, per unit area there (the cosine
// at next when on a surface, 1 / d²; unchanged at infinity), with the direction and distance at hand.
float area_density(float pdf, Vector3f wn, const DensityTarget& next, float inv_d2) {
    if (next.infinite) return pdf;
    if (next.ng != Normal3f{}) pdf *= std::abs(dot(Vector3f(next.ng), wn));
    return pdf * inv_d2;
}

} // namespace

float vertex_pdf(const PathContext& ctx, const PathVertex& v, Vector3f wp, Vector3f wn,
                 const DensityTarget& next, float inv_d2) {
    float pdf = 0;
    switch (v.type) {
    case VertexType::Light:
        return 0; // lights go through pdf_light (above)
    case VertexType::Camera:
        pdf = ctx.scene.camera_pdf_we(Ray{v.p, wn, kInfinity, ctx.time}).dir.value;
        break;
    case VertexType::Surface:
        pdf = v.bsdf.pdf(wp, wn).value;
        break;
    case VertexType::Medium:
        // The phase function takes the directions of travel: in along -wp, out along wn.
        pdf = v.phase.p(dot(-wp, wn));
        break;
    }
    return area_density(pdf, wn, next, inv_d2);
}

float vertex_pdf(const PathContext& ctx, const PathVertex& v, const PathVertex* prev,
                 const PathVertex& next) {
    if (v.type == VertexType::Light) return pdf_light(ctx, v, next);
    Segment to_next = segment(v, next);
    if (!(to_next.inv_d2 > 0)) return 0;
    Vector3f wp;
    if (prev) {
        Segment to_prev = segment(v, *prev);
        if (!(to_prev.inv_d2 > 0)) return 0;
        wp = to_prev.w;
    }
    return vertex_pdf(ctx, v, wp, to_next.w, next, to_next.inv_d2);
}

EndScattering end_scattering(const PathVertex& v, Vector3f w, TransportMode mode) {
    EndScattering e;
    switch (v.type) {
    case VertexType::Surface: {
        const BSDFEval b = v.bsdf.eval(v.wo, w, mode);
        e.f = b.f.s;
        if (mode == TransportMode::Importance) e.f *= shading_normal_adjoint(v.hit, v.wo, w);
        e.pdf_w = b.pdf_wi;
        e.pdf_wo = b.pdf_wo;
        e.has_pdfs = b.has_pdfs;
        break;
    }
    case VertexType::Medium: {
        // The phase function of the angle between the directions of travel; symmetric.
        const float p = v.phase.p(dot(-v.wo, w));
        e.f = SampledSpectrum(p);
        e.pdf_w = e.pdf_wo = p;
        e.has_pdfs = true;
        break;
    }
    default:
        break;
    }
    return e;
}

namespace {

// Whether an end's end_scattering stands for vertex_pdf there: it holds the densities, at a surface or
// medium vertex entered from a predecessor.
bool scatters(const EndScattering* e, const PathVertex& v, const PathVertex* v_m) {
    return e && e->has_pdfs && v_m && (v.type == VertexType::Surface || v.type == VertexType::Medium);
}

} // namespace

JoinDensities join_densities(const PathContext& ctx, const PathVertex* qs, const PathVertex* qs_m,
                             const PathVertex& pt, const PathVertex* pt_m, const EndScattering* at_qs,
                             const EndScattering* at_pt) {
    JoinDensities j;
    if (!qs) {
        j.pt_rev = pdf_light_origin(ctx, pt, *pt_m);
        j.pt_m_rev = pdf_light(ctx, pt, *pt_m);
        return j;
    }
    const Segment joint = segment(pt, *qs); // from pt towards qs
    if (!(joint.inv_d2 > 0)) {
        j.joined = false;
        return j;
    }
    const bool qs_given = scatters(at_qs, *qs, qs_m), pt_given = scatters(at_pt, pt, pt_m);
    j.pt_rev = qs_given ? area_density(at_qs->pdf_w, -joint.w, density_target(pt), joint.inv_d2)
                        : vertex_pdf(ctx, *qs, qs_m ? qs->wo : Vector3f{}, -joint.w, pt, joint.inv_d2);
    j.qs_rev = pt_given ? area_density(at_pt->pdf_w, joint.w, density_target(*qs), joint.inv_d2)
                        : vertex_pdf(ctx, pt, pt_m ? pt.wo : Vector3f{}, joint.w, *qs, joint.inv_d2);
    if (pt_m) {
        const float inv_d2 = inv_distance_squared(pt, *pt_m);
        j.pt_m_rev = pt_given ? area_density(at_pt->pdf_wo, pt.wo, density_target(*pt_m), inv_d2)
                              : vertex_pdf(ctx, pt, joint.w, pt.wo, *pt_m, inv_d2);
    }
    if (qs_m) {
        const float inv_d2 = inv_distance_squared(*qs, *qs_m);
        j.qs_m_rev = qs_given ? area_density(at_qs->pdf_wo, qs->wo, density_target(*qs_m), inv_d2)
                              : vertex_pdf(ctx, *qs, -joint.w, qs->wo, *qs_m, inv_d2);
    }
    return j;
}

SampledSpectrum vertex_le(const PathContext& ctx, const PathVertex& v, const PathVertex& towards) {
    if (!v.is_light()) return SampledSpectrum(0.0f);
    Vector3f w = towards.p - v.p;
    float d2 = length_squared(w);
    if (!(d2 > 0)) return SampledSpectrum(0.0f);
    w = w / std::sqrt(d2);
    if (v.is_infinite_light()) {
        SampledSpectrum le(0.0f);
        // The ray from the vertex that sees the environment: a portal light's radiance depends on where the
        // ray starts (v.p only marks the direction).
        for (const Light* l : ctx.scene.infinite_lights) le += l->le(Ray{towards.p, -w}, ctx.tc.lambda).s;
        return le;
    }
    if (v.type == VertexType::Surface) return v.hit.area_light->radiance(v.hit, w, ctx.tc.lambda).s;
    return SampledSpectrum(0.0f);
}

int walk(const PathContext& ctx, Ray ray, SampledSpectrum beta, float pdf_dir, int max_vertices,
         TransportMode mode, int ch, PathVertex* path) {
    if (max_vertices <= 0) return 0;
    ThreadContext& tc = ctx.tc;
    Sampler& sampler = tc.sampler;
    int n = 0;
    float pdf_fwd = pdf_dir;
    // The path's densities in every channel relative to the sampling channel's (free flights only).
    SampledSpectrum r_u(1.0f);
    for (int crossings = 0; crossings < kMaxCrossings;) {
        if (beta.is_black() || !beta.is_finite()) break;
        PathVertex& v = path[n];
        PathVertex& prev = path[n - 1];
        // The hit is found in the vertex it may become (a medium vertex made first overwrites it).
        SurfaceHit& hit = v.hit;
        hit = SurfaceHit{};
        ++tc.rays;
        bool found = ctx.scene.intersect(ray, &hit);
        if (ray.medium) {
            bool scattered = false, terminated = false;
            const Medium* medium = ray.medium;
            SampledSpectrum t_maj = sample_t_maj(
                ray, found ? hit.t : kInfinity, sampler.get_1d(), ctx.rng, tc.lambda, ch,
                [&](Point3f p, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum t_m) {
                    MediumEvent event = choose_medium_event(mp, sigma_maj, ch, ctx.rng.uniform_float(),
                                                            medium->is_homogeneous());
                    if (event == MediumEvent::Absorb) {
                        terminated = true;
                        return false;
                    }
                    if (event == MediumEvent::Scatter) {
                        // A real scattering event: a medium vertex.
                        float pdf = t_m[ch] * mp.sigma_s[ch];
                        beta *= t_m * mp.sigma_s / pdf;
                        r_u *= t_m * mp.sigma_s / pdf;
                        Vector3f travel = ray.d / length(ray.d);
                        v = PathVertex{};
                        v.type = VertexType::Medium;
                        v.p = p;
                        v.wo = -travel;
                        v.medium = medium;
                        v.phase = mp.phase;
                        float avg = r_u.average();
                        v.beta = avg > 0 ? beta / avg : SampledSpectrum(0.0f);
                        v.pdf_fwd = convert_density(prev, pdf_fwd, v);
                        if (++n >= max_vertices) {
                            terminated = true;
                            return false;
                        }
                        float phase_pdf = 0;
                        Vector3f wi = mp.phase.sample(travel, sampler.get_2d(), &phase_pdf);
                        if (!(phase_pdf > 0)) {
                            terminated = true;
                            return false;
                        }
                        // β *= p / pdf = 1 (Henyey-Greenstein is sampled exactly, and is symmetric, so the
                        // reverse density is the same number).
                        pdf_fwd = phase_pdf;
                        prev.pdf_rev = convert_density(v, phase_pdf, prev);
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
            if (terminated || beta.is_black() || !beta.is_finite()) return n;
            if (scattered) continue;
            SampledSpectrum rel = relative_to_channel(t_maj, ch);
            beta *= rel;
            r_u *= rel;
            if (beta.is_black()) return n;
        }
        float avg = r_u.average();
        if (!(avg > 0)) return n;
        if (!found) {
            // A camera ray that leaves the scene ends at the environment: a light vertex at infinity (its p
            // only gives the direction, from the previous vertex).
            if (mode == TransportMode::Radiance && !ctx.scene.infinite_lights.empty()) {
                v = PathVertex{};
                v.type = VertexType::Light;
                v.p = prev.p + ray.d / length(ray.d) * std::max(2 * ctx.scene_radius, 1.0f);
                v.beta = beta / avg;
                v.pdf_fwd = pdf_fwd;
                ++n;
            }
            break;
        }
        footprint_from_camera(hit, ctx.scene, tc.sampler.samples_per_pixel());
        // Built in the vertex (assign_in_place): a BSDF copied out of the call's result would stall.
        assign_in_place(v.bsdf, [&] { return surface_bsdf(hit, tc.lambda, tc.arena); });
        const BSDF& bsdf = v.bsdf;
        if (!bsdf) {
            // An interface between media: crossed, not a vertex.
            assign_in_place(ray, [&] { return hit.spawn_ray(ray.d); });
            ++crossings;
            continue;
        }
        // Every field a surface vertex reads (the hit is in place already).
        v.type = VertexType::Surface;
        v.delta = false;
        v.pdf_rev = 0;
        v.medium = nullptr;
        v.light = nullptr;
        v.p = hit.p;
        v.p_error = hit.p_error;
        v.ng = hit.n;
        v.ns = hit.ns;
        v.wo = hit.wo;
        v.beta = beta / avg;
        v.pdf_fwd = convert_density(prev, pdf_fwd, v);
        ++n;
        if (n >= max_vertices || bsdf.flags() == kNone) break;
        float u_lobe = sampler.get_1d_if(bsdf.reads_lobe_sample());
        Point2f u_dir = sampler.get_2d();
        auto bs = bsdf.sample(hit.wo, u_lobe, u_dir, mode);
        if (!bs) break;
        pdf_fwd = bs->pdf_is_proportional ? bsdf.pdf(hit.wo, bs->wi, mode).value : bs->pdf.value;
        float cos_i = std::abs(dot(bs->wi, Vector3f(hit.ns)));
        if (mode == TransportMode::Importance) cos_i *= shading_normal_adjoint(hit, hit.wo, bs->wi);
        beta *= throughput_weight(bs->f, cos_i, bs->pdf);
        float pdf_rev = bsdf.pdf(bs->wi, hit.wo, other(mode)).value;
        if (bs->is_specular()) {
            v.delta = true;
            pdf_rev = pdf_fwd = 0;
        }
        prev.pdf_rev = convert_density(v, pdf_rev, prev);
        assign_in_place(ray, [&] { return hit.spawn_ray(bs->wi); });
        ray.medium = walk_into(ctx, ray.medium, hit);
    }
    return n;
}

SampledSpectrum connection_transmittance(const PathContext& ctx, const PathVertex& a, const PathVertex& b,
                                         int ch) {
    Ray ray;
    ShadowTarget target;
    if (b.is_infinite_light()) {
        Vector3f w = normalize(b.p - a.p);
        target.at_infinity = true;
        target.wi = w;
        if (a.type == VertexType::Surface)
            ray = a.hit.spawn_ray(w);
        else
            ray = Ray{a.p, w, kInfinity, ctx.time, a.medium_towards(b.p)};
    } else {
        target = ShadowTarget{b.p, b.p_error, b.ng, false, {}};
        if (a.type == VertexType::Surface) {
            if (!b.on_surface()) {
                ray = a.hit.spawn_ray_to(b.p);
            } else {
                ray = spawn_ray_to(a.p, a.p_error, a.ng, b.p, b.p_error, b.ng);
                ray.medium = a.hit.medium_for(b.p - a.p);
            }
        } else {
            Point3f q = b.on_surface() ? offset_ray_origin(b.p, b.p_error, b.ng, a.p - b.p) : b.p;
            ray = Ray{a.p, q - a.p, 1 - 1e-4f, ctx.time, a.medium_towards(b.p)};
        }
    }
    ray.time = ctx.time;
    // Leaving in vacuum with nothing passable on the way: blocked or clear, without the tracking state.
    // Exact before entered_medium(), which keeps a vacuum ray in vacuum; a subsurface material's interior
    // is a medium even in a scene without named media, so the scene's media do not decide it.
    if (is_plain_occlusion(ctx.scene, ray)) {
        ++ctx.tc.rays;
        return SampledSpectrum(ctx.scene.occluded(ray) ? 0.0f : 1.0f);
    }
    // From a textured subsurface shape's boundary into it: evaluated at a, unless a's subpath is inside.
    std::optional<EntryMedium> entry;
    if (a.type == VertexType::Surface)
        ray.medium = entered_medium(ray.medium, a.hit, ctx.tc.lambda, [&] { return &entry.emplace(); });
    SampledSpectrum r_u(1.0f), r_l(1.0f);
    SampledSpectrum t =
        shadow_transmittance(ctx.scene, ray, target, ch, ctx.rng, ctx.tc.lambda, &r_u, &r_l, &ctx.tc.rays);
    if (t.is_black()) return t;
    // One-sample spectral MIS over the tracking channel (pbrt-v4's Integrator::Tr): T / avg(r_l).
    float avg = r_l.average();
    return avg > 0 ? t / avg : SampledSpectrum(0.0f);
}

SampledSpectrum connect_g(const PathContext& ctx, const PathVertex& a, const PathVertex& b, const Segment& ab,
                          int ch) {
    float g = ab.inv_d2;
    if (a.on_surface()) g *= std::abs(dot(Vector3f(a.ns), ab.w));
    if (b.on_surface()) g *= std::abs(dot(Vector3f(b.ns), ab.w));
    if (!(g > 0)) return SampledSpectrum(0.0f);
    return connection_transmittance(ctx, a, b, ch) * g;
}

bool connect_sampled_light(const PathContext& ctx, const PathVertex& pt, float u_light, Point2f u,
                           int channel, PathVertex* sampled, SampledSpectrum* l, EndScattering* at_pt) {
    float pmf = 0;
    const Light* light = ctx.scene.light_sampler.sample(u_light, &pmf);
    if (!light || !(pmf > 0)) return false;
    LightSampleContext lc = pt.type == VertexType::Surface ? LightSampleContext(pt.hit)
                                                           : LightSampleContext(pt.p, {}, {}, ctx.time);
    std::optional<LightLiSample> ls = light->sample_li(lc, u, ctx.tc.lambda);
    if (!ls || ls->biradiance.s.is_black() || !(ls->pdf.value > 0)) return false;
    // Every field a light vertex reads: *sampled may be scratch that held another endpoint.
    sampled->type = VertexType::Light;
    sampled->delta = false;
    sampled->light = light;
    sampled->medium = light->medium;
    sampled->pdf_rev = 0;
    if (ls->at_infinity) {
        sampled->p = pt.p + ls->wi * std::max(2 * ctx.scene_radius, 1.0f);
        sampled->p_error = Vector3f{};
        sampled->ng = sampled->ns = Normal3f{};
    } else {
        sampled->p = ls->p_light;
        sampled->p_error = ls->p_light_error;
        sampled->ng = sampled->ns = ls->n_light;
    }
    // The biradiance is L / p_ω (or I / r² for a point): the light's end of the path over its density.
    sampled->beta = ls->biradiance.s / pmf;
    sampled->pdf_fwd = pdf_light_origin(ctx, *sampled, pt);
    const Segment to_light = segment(pt, *sampled);
    if (!(to_light.inv_d2 > 0)) return false;
    assign_in_place(*at_pt, [&] { return end_scattering(pt, to_light.w, TransportMode::Radiance); });
    *l = pt.beta * at_pt->f * sampled->beta;
    if (pt.on_surface()) *l *= std::abs(dot(ls->wi, Vector3f(pt.ns)));
    if (!l->is_black()) *l *= connection_transmittance(ctx, pt, *sampled, channel);
    return true;
}

int trace_light_subpath(const PathContext& ctx, float u_light, Point2f u_pos, Point2f u_dir, int max_depth,
                        int channel, PathVertex* path) {
    float pmf = 0;
    const Light* light = ctx.scene.light_sampler.sample(u_light, &pmf);
    // Results built where they are kept, not copied (util/in_place.h).
    const std::optional<LightLeSample> les =
        light && pmf > 0 ? light->sample_le_at(ctx.time, u_pos, u_dir, ctx.tc.lambda) : std::nullopt;
    if (!les || !(les->pdf_pos.value > 0) || !(les->pdf_dir.value > 0) || les->flux.is_black()) return 0;
    PathVertex& l0 = path[0];
    assign_in_place(l0, [] { return PathVertex{}; });
    l0.type = VertexType::Light;
    l0.light = light;
    l0.p = les->ray.o;
    l0.ng = l0.ns = les->n;
    l0.medium = light->medium;
    l0.beta = les->radiance.s;
    l0.pdf_fwd = pmf * les->pdf_pos.value;
    const Vector3f d = les->ray.d;
    int n = 1 + walk(ctx, Ray{les->ray.o, d, les->ray.tmax, ctx.time, light->medium_towards(d, les->n)},
                     (les->flux / pmf).s, les->pdf_dir.value, max_depth, TransportMode::Importance, channel,
                     path + 1);
    if (l0.is_infinite_light()) {
        if (n > 1) {
            path[1].pdf_fwd = les->pdf_pos.value;
            if (path[1].on_surface()) path[1].pdf_fwd *= std::abs(dot(d, Vector3f(path[1].ng)));
        }
        l0.pdf_fwd = infinite_light_density(ctx, d);
    }
    return n;
}

} // namespace illum
