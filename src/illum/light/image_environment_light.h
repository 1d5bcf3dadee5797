// An environment light from an image (EnvironmentMap, any layout), rotated by world_from_light and
// scaled. Directions are importance sampled by a 2D piecewise-constant density over the image whose
// weights are the texels' radiance times their solid angle, i.e. proportional to L · dω/(du dv): the
// sin θ of the latitude-longitude layout, the constant 4π of the equal-area octahedral one, the layout's
// own Jacobian otherwise. A sampled uv of density p(u, v) is the direction ω(u, v) with density
// p(ω) = p(u, v) / (dω/(du dv)) evaluated at the same uv, so pdf_li is exact.
//
// Every texel of non-zero solid angle also gets a small floor weight (1e-3 of the mean), so every
// direction where the bilinearly filtered radiance is non-zero can be sampled: light sampling on its own
// stays unbiased, and a single bright texel still receives ~99.9% of the samples.
//
// A map with no energy (all black) gives a light of zero radiance and zero power: it is never picked by
// the power-based light sampler, and sampling falls back to uniform over the image (documented fallback).
#pragma once

#include <memory>

#include "illum/envmap/environment_map.h"
#include "illum/light/light.h"
#include "illum/math/distribution.h"
#include "illum/math/transform.h"

namespace illum {

// How sample_li picks directions: "importance" (the map's distribution, the default), "uniform" (over
// the sphere), or "none" (no light samples; the environment is reached only by BSDF sampling — for
// measuring what importance sampling gains).
enum class EnvSampling { Importance, Uniform, None };

class ImageEnvironmentLight final : public Light {
public:
    ImageEnvironmentLight(EnvironmentMap map, const Transform& world_from_light, float scale,
                          EnvSampling sampling = EnvSampling::Importance);

    void preprocess(const Bounds3f& scene_bounds) override;
    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const override;
    Radiance3 le(const Ray& ray, const SampledWavelengths& lambda) const override {
        return radiance(ray.d, lambda);
    }
    // π r² ∫ L dω with r the scene's bounding radius (the flux through the scene's disk).
    Power3 power() const override;
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    // The map's distribution at the direction the photon comes from (-ray.d), whatever the sampling mode.
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    // Radiance arriving from world direction w (towards the environment). Light::radiance (emission from
    // a surface point) stays visible beside it.
    using Light::radiance;
    // Its texels' RGB, uplifted as an illuminant in spectral mode.
    Radiance3 radiance(Vector3f w, const SampledWavelengths& lambda) const;
    // Illuminance-like integral ∫_{z>0} lum(L) cos θ dω over the upper hemisphere in light space
    // (before scale), for pbrt-v4's "illuminance" normalisation.
    float upper_hemisphere_irradiance() const;
    float scale() const { return scale_; }
    const EnvironmentMap& map() const { return map_; }

    // The importance-sampling density over directions in light space (for tests).
    float pdf_light_space(Vector3f d) const;

private:
    EnvironmentMap map_;
    Transform world_from_light_, light_from_world_;
    float scale_;
    EnvSampling sampling_;
    Distribution2D distribution_;
    Color3 integral_; // ∫ L dω (before scale)
    Point3f scene_center_;
    float scene_radius_ = 0;
};

} // namespace illum
