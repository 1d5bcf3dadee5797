// Volumetric path tracing (pbrt-v4's "volpath"; Miller, Georgiev & Jarosz 2019, "A Null-Scattering Path
// Integral Formulation of Light Transport"; PBR 4th ed. §14.2). In a medium the path samples tentative
// collisions against the majorant (delta tracking, sample_majorant.h) and at each chooses absorption,
// real scattering or a null collision with probabilities σ_a/σ_maj, σ_s/σ_maj and σ_n/σ_maj; emission of
// the medium (σ_a Le) is collected at every collision. At surfaces and real scattering events next-event
// estimation samples a light, its shadow ray passing through surfaces without material and estimating
// the media's transmittance: exactly (exp(-σ_t d)) in a homogeneous medium, by ratio tracking in others.
//
// Chromatic media: the distances are sampled with one channel's coefficients, chosen uniformly per path,
// and every estimate is divided by the average over the channels of the path's density (spectral MIS:
// the rescaled densities r_u of the unidirectional technique and r_l of light sampling, relative to the
// sampling channel's), so a colour whose extinction differs from the sampled one does not explode the
// variance. Light and BSDF/phase sampling are combined by the balance heuristic on those densities.
//
// The exact homogeneous transmittance is a technique of its own (density 1 along the segment, where pbrt-v4's
// ratio tracking, with a majorant equal to σ_t, has a Bernoulli estimate of density T); both sides of MIS
// weigh it so (light sampling's r_l omits T there), which removes the shadow rays' binary noise in fog.
#pragma once

#include "illum/bsdf/bxdf.h"
#include "illum/light/light.h"
#include "illum/math/rng.h"
#include "illum/medium/entry_medium.h"
#include "illum/medium/equiangular.h"
#include "illum/medium/henyey_greenstein.h"
#include "illum/render/integrator.h"

namespace illum {

class Medium;

class VolPathIntegrator final : public Integrator {
public:
    // max_depth: the number of scattering events, surface or volume (negative: unbounded).
    // caustics_by_light_tracing: leave out the paths that volpath_caustics.h's light tracing renders (an area
    // light found right after a specular bounce by a path whose first vertex was not specular).
    VolPathIntegrator(const Scene& scene, int max_depth, bool caustics_by_light_tracing = false)
        : Integrator(scene), max_depth_(max_depth), caustics_by_light_tracing_(caustics_by_light_tracing) {
        for (const auto& l : scene.lights) point_lights_ = point_lights_ || l->position().has_value();
        entry_media_ = has_entry_media(scene);
    }
    Radiance3 estimate(const Ray& camera_ray, ThreadContext& tc) const override;
    bool starts_at_camera_hit() const override { return true; }

    // Next-event estimation's light for ctx and its probability: the scene's light sampler at a surface
    // point; by power at a point in a medium (ctx.n zero), where the equiangular sampling of a segment picks
    // its light by power before the point is known and both strategies' MIS weights assume one choice.
    const Light* pick_light(const LightSampleContext& ctx, float u, float* pmf) const {
        return ctx.n == Normal3f{} ? scene_.light_sampler.sample(u, pmf)
                                   : scene_.direct_light_sampler.sample(ctx, u, pmf);
    }
    float pick_light_pmf(const LightSampleContext& ctx, const Light* light) const {
        return ctx.n == Normal3f{} ? scene_.light_sampler.pmf(light)
                                   : scene_.direct_light_sampler.pmf(ctx, light);
    }

    // Whether the scene has media at all: without, "volpath" renders with the surface path tracer.
    static bool needed(const Scene& scene);
    // Whether some material encloses a medium evaluated where a path enters it (textured subsurface).
    static bool has_entry_media(const Scene& scene);

    // The state of one path: throughput β and the rescaled densities r_u, r_l (per channel, relative to the
    // sampling channel's), the sampling channel and the generator for the tracking's tentative collisions.
    struct PathState {
        SampledSpectrum beta{1.0f}, r_u{1.0f}, r_l{1.0f};
        int channel = 0;
        PCG32 rng;
        HomogeneousCache media;
        float time = 0; // the camera sample's time (motion blur): every ray of the path has it
        // The media of textured subsurface shapes (entry_medium.h): 0 the path's, evaluated where it entered
        // the shape; 1 a shadow ray's, from the boundary into the shape. Made when first needed.
        EntryMediumSlots<2> entry_media;
        // The medium a ray leaving `hit` travels in, given next = hit.medium_for(its direction), evaluated
        // into slot `slot`.
        const Medium* enter(const Medium* next, const SurfaceHit& hit, const SampledWavelengths& lambda,
                            int slot) {
            return entered_medium(next, hit, lambda, [&] {
                EntryMedium* m = entry_media.get(slot);
                media.forget(m); // re-evaluated in place
                return m;
            });
        }
    };
    // Where next-event estimation starts: a surface point with its BSDF, or a point in a medium with its
    // phase function (then `hit` and `bsdf` are null).
    // A stretch of the path's ray through a homogeneous medium, from its origin o (unit direction d) to
    // t_end, with the rescaled density r_u at o: single scattering towards a point or spot light is sampled
    // there both by the free-flight distance and equiangularly (medium/equiangular.h), weighed by MIS.
    struct Segment {
        Point3f o;
        Vector3f d;
        float t_end = 0;
        SampledSpectrum r_u0;
        // The equiangular distribution towards the light that sample_equiangular chose (reused by the
        // free-flight side's weight when next-event estimation picks the same light).
        const Light* light = nullptr;
        std::optional<Equiangular> eq;
        const Equiangular* towards(const Light& l) {
            if (&l != light) {
                light = &l;
                // Only where the light reaches (a spot light's cone): outside it the light adds nothing, so
                // no density is given there, and a segment that misses the cone takes no sample.
                float a = 0, b = t_end;
                if (l.illuminated_interval(o, d, &a, &b))
                    eq = Equiangular::make(o, d, a, b, *l.position());
                else
                    eq.reset();
            }
            return eq ? &*eq : nullptr;
        }
    };
    struct Vertex {
        const SurfaceHit* hit = nullptr;
        const BSDF* bsdf = nullptr;
        Point3f p;
        const Medium* medium = nullptr; // the medium around a medium vertex
        Vector3f travel;                // the incoming direction of travel (medium vertex)
        HenyeyGreenstein phase;
        // A medium vertex on a homogeneous segment: the segment, the distance along it and the free-flight
        // density σ_s T of scattering there, per channel.
        Segment* segment = nullptr;
        float t = 0;
        SampledSpectrum p_free_flight;
    };

private:
    // Next-event estimation: one light picked by power, its contribution weighed by spectral MIS.
    SampledSpectrum sample_light(const Vertex& v, PathState& path, ThreadContext& tc) const;
    // Single scattering towards a point or spot light on a homogeneous segment, at an equiangularly sampled
    // distance; beta and r_u are the path's at the segment's origin.
    SampledSpectrum sample_equiangular(Segment& seg, const Medium& medium, SampledSpectrum beta,
                                       PathState& path, ThreadContext& tc) const;

    int max_depth_;
    bool caustics_by_light_tracing_;
    bool point_lights_ = false; // whether the scene has point or spot lights (equiangular sampling)
    bool entry_media_ = false;  // has_entry_media: else rays need not ask PathState::enter
};

} // namespace illum
