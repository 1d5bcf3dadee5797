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
#include "illum/math/bounds.h"
#include "illum/radiometry/quantity.h"

namespace illum {

enum class LightType : std::uint8_t {
    DeltaPosition,  // point, spot
    DeltaDirection, // directional
    Area,           // emitting surfaces
    Infinite,       // environments
};
inline bool is_delta(LightType t) { return t == LightType::DeltaPosition || t == LightType::DeltaDirection; }

// The receiving point.
struct LightSampleContext {
    Point3f p;
    Vector3f p_error;
    Normal3f n; // geometric normal; zero when not on a surface

    LightSampleContext() = default;
    LightSampleContext(Point3f p_, Vector3f err, Normal3f n_) : p(p_), p_error(err), n(n_) {}
    explicit LightSampleContext(const SurfaceHit& h) : p(h.p), p_error(h.p_error), n(h.n) {}
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

class Light {
public:
    explicit Light(LightType type) : type_(type) {}
    virtual ~Light() = default;
    LightType type() const { return type_; }

    // Called once the scene bounds are known (environment and directional lights need its radius).
    virtual void preprocess(const Bounds3f&) {}
    virtual std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u) const = 0;
    // Density (per steradian at ctx) with which sample_li returns direction wi; for area lights `hit` is
    // where the ray along wi met the light.
    virtual SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const = 0;
    // Radiance leaving the light's surface at hit towards w (area lights).
    virtual Radiance3 radiance(const SurfaceHit&, Vector3f) const { return {}; }
    // Radiance arriving along a ray that leaves the scene (environment lights).
    virtual Radiance3 le(const Ray&) const { return {}; }
    virtual Power3 power() const = 0;

    // Position in the scene's light list, set by the scene (for selection pmfs).
    std::uint32_t index = 0;

private:
    LightType type_;
};

} // namespace illum
