// Direct lighting: the reflection equation alone. At the first non-specular surface the radiance
// reflected from every light is added: exactly for point and directional sources (a sum over lights),
// and for area and environment lights by one light sample and one BSDF sample combined with multiple
// importance sampling (an estimate of the integral over the hemisphere). Specular surfaces before it
// are followed (Whitted-style) up to max_depth.
#pragma once

#include "illum/render/integrator.h"

namespace illum {

class DirectIntegrator final : public Integrator {
public:
    DirectIntegrator(const Scene& scene, int max_depth) : Integrator(scene), max_depth_(max_depth) {}
    Radiance3 estimate(const Ray& camera_ray, ThreadContext& tc) const override {
        return radiance(camera_ray, tc);
    }
    Radiance3 radiance(Ray ray, ThreadContext& tc) const;
    bool starts_at_camera_hit() const override { return true; }

private:
    Radiance3 reflected_from(const Light& light, const SurfaceHit& hit, const BSDF& bsdf,
                             ThreadContext& tc) const;
    int max_depth_;
};

} // namespace illum
