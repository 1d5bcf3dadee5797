// The emitter interface. A light answers: the radiance arriving from it along a ray (area and
// environment lights), a sampled incident direction at a receiving point with its solid-angle pdf
// (or a delta), and its total emitted power (for light selection by power).
//
// A sample carries the biradiance E = L / p(ω) (or I / r² for a point source): the one-sample estimate
// of the incident light before the cosine, so the reflection equation's estimate is f · E · cos θ.
#pragma once

#include <cstdint>
#include <optional>

#include "illum/geometry/ray.h"
#include "illum/geometry/surface_hit.h"
#include "illum/light/light_bounds.h"
#include "illum/math/bounds.h"
#include "illum/radiometry/quantity.h"
#include "illum/radiometry/sampled_wavelengths.h"

namespace illum {

enum class LightType : std::uint8_t {
    DeltaPosition,  // point, spot
    DeltaDirection, // directional
    Area,           // emitting surfaces
    Infinite,       // environments
};
inline bool is_delta(LightType t) { return t == LightType::DeltaPosition || t == LightType::DeltaDirection; }

// The receiving point, at the path's time (a moving light is sampled where it is then).
struct LightSampleContext {
    Point3f p;
    Vector3f p_error;
    Normal3f n; // geometric normal; zero when not on a surface
    float time = 0;

    LightSampleContext() = default;
    LightSampleContext(Point3f p_, Vector3f err, Normal3f n_, float time_ = 0)
        : p(p_), p_error(err), n(n_), time(time_) {}
    explicit LightSampleContext(const SurfaceHit& h) : p(h.p), p_error(h.p_error), n(h.n), time(h.time) {}
};

struct LightLiSample {
    Vector3f wi;            // unit direction from the receiver towards the light
    Radiance3 radiance;     // incident radiance (zero for delta lights: they have none per steradian)
    Biradiance3 biradiance; // radiance / pdf, or I / r², or the directional light's irradiance
    SolidAnglePdf pdf;      // per steradian; 1 for delta lights (a probability, not a density)
    Point3f p_light;        // the point on the light (unused when at_infinity)
    Vector3f p_light_error;
    Normal3f n_light;
    bool at_infinity = false;
};

// A photon leaving the light (light tracing, photon mapping): sample_le draws an origin and a direction.
// The pdfs are kept apart, as bidirectional methods need them: pdf_pos is per unit area on the light (or
// on the disk an infinite light emits from), and 1 as a probability for a delta position (point, spot);
// pdf_dir is per steradian, and 1 as a probability for a delta direction (directional light).
// `flux` is the one-sample estimate of the power the photon carries, so E[flux] = power():
//   area / environment: L |cos θ| / (p_pos p_dir);  point / spot: I(ω) / p_dir;  directional: E / p_pos.
struct LightLeSample {
    Ray ray;            // origin on the light, unit direction of travel
    Normal3f n;         // the emitter's normal at the origin; zero for points and infinite lights
    Radiance3 radiance; // radiance along the ray (zero for delta lights)
    AreaPdf pdf_pos;
    SolidAnglePdf pdf_dir;
    Power3 flux;
    // Area lights: the sampled point itself (ray.o is moved off the surface, towards the photon's side)
    // and its error bound, from which a connection to the other side of a two-sided emitter must start.
    Point3f p_surface;
    Vector3f p_error;
};

class Light {
public:
    explicit Light(LightType type) : type_(type) {}
    virtual ~Light() = default;
    LightType type() const { return type_; }

    // Called once the scene bounds are known (environment and directional lights need its radius).
    virtual void preprocess(const Bounds3f&) {}
    // lambda: the path's wavelengths (the values come at them, or in RGB in RGB mode).
    virtual std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                                   const SampledWavelengths& lambda) const = 0;
    // Density (per steradian at ctx) with which sample_li returns direction wi; for area lights `hit` is
    // where the ray along wi met the light (at the ray's time, ctx's).
    virtual SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const = 0;
    // Radiance leaving the light's surface at hit towards w (area lights).
    virtual Radiance3 radiance(const SurfaceHit&, Vector3f, const SampledWavelengths&) const { return {}; }
    // Radiance arriving along a ray that leaves the scene (environment lights).
    virtual Radiance3 le(const Ray&, const SampledWavelengths&) const { return {}; }
    // In RGB (light selection by power does not depend on the mode).
    virtual Power3 power() const = 0;
    // Where the light is, which way and how strongly it emits, for light samplers that choose by the
    // receiver (light_bounds.h); nullopt for lights at infinity and those a sampler should treat like them
    // (picked apart from the bounded ones, uniformly).
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
    // The area density with which sample_le() starts a photon at the point of `hit` on an area light (for
    // weighing a light seen directly against the camera's sampling); zero for the other lights.
    virtual AreaPdf pdf_le_position(const SurfaceHit&) const { return AreaPdf(0); }
    // A point or spot light's position (for sampling distances towards it in media); none for the others.
    virtual std::optional<Point3f> position() const { return std::nullopt; }
    // Narrows [*t0, *t1] to the part of the line o + t d (unit d) that the light can reach directly (a spot
    // light's cone); false when none of it. Equiangular sampling in media samples only there. The default
    // keeps the whole interval.
    virtual bool illuminated_interval(Point3f, Vector3f, float*, float*) const { return true; }
    // Photon emission: an origin from u1 and a direction from u2 (see LightLeSample); nullopt when the
    // light emits nothing there. Infinite and directional lights need preprocess() first.
    virtual std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                                   const SampledWavelengths& lambda) const = 0;
    // The same at the path's time (motion blur), which the photon's ray carries: a moving light emits from
    // where it is then; the still ones emit as sample_le() does.
    virtual std::optional<LightLeSample> sample_le_at(float time, Point2f u1, Point2f u2,
                                                      const SampledWavelengths& lambda) const {
        std::optional<LightLeSample> s = sample_le(u1, u2, lambda);
        if (s) s->ray.time = time;
        return s;
    }
    // The densities with which sample_le() would emit `ray` (origin on the light, unit direction of
    // travel; n: the emitter's normal at the origin, zero for points and infinite lights), in sample_le's
    // conventions: *pos per unit area (1 as a probability for a delta position; for infinite and
    // directional lights the disk density 1 / (π r²), whatever the origin), *dir per steradian (1 as a
    // probability for a delta direction that the ray follows, 0 for any other). Bidirectional methods
    // weigh their strategies with it (PBR 4th ed. §16.3, Light::PDF_Le; Veach 1997 §10.2). The ray's time
    // is the path's (a moving light's densities are those of its pose then).
    virtual void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const = 0;

    // Position in the scene's light list, set by the scene (for selection pmfs).
    std::uint32_t index = 0;
    // The media around the light, set by the scene: an area light on a surface that separates two media
    // has the surface's interface; any other light sits in `medium` (pbrt-v4: the outside medium current
    // at its directive). Photons leave into medium_towards(their direction, the emitter's normal).
    const Medium* medium = nullptr;
    const MediumInterface* medium_interface = nullptr;
    const Medium* medium_towards(Vector3f d, Normal3f n) const {
        if (!medium_interface) return medium;
        return dot(d, n) > 0 ? medium_interface->outside : medium_interface->inside;
    }

private:
    LightType type_;
};

// A photon of an infinite light arriving from direction wi (towards the light) with radiance l: its
// origin is uniform on the disk of radius r centred at c + r wi, facing -wi, so it covers the scene's
// bounding sphere (centre c, radius r). p_pos = 1 / (π r²); the direction is perpendicular to the disk.
LightLeSample disk_emission(Point3f c, float r, Vector3f wi, Point2f u, Radiance3 l, SolidAnglePdf pdf_dir);
// disk_emission's position density, 1 / (π r²) (0 before the scene's radius is known).
inline AreaPdf disk_emission_pdf(float r) { return r > 0 ? AreaPdf(1 / (kPi * r * r)) : AreaPdf(0); }

} // namespace illum
