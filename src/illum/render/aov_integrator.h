// Debug passes: the albedo (the first hit's material reflectance) and the shading normal (world space,
// components in [-1, 1]) of the first surface seen. Not radiance.
#pragma once

#include "illum/render/integrator.h"

namespace illum {

class AovIntegrator final : public Integrator {
public:
    enum class Pass { Albedo, Normal };
    AovIntegrator(const Scene& scene, Pass pass) : Integrator(scene), pass_(pass) {}

    Color3 estimate(const Ray& camera_ray, ThreadContext& tc) const override {
        Ray ray = camera_ray;
        for (int i = 0; i < 64; ++i) {
            SurfaceHit hit;
            if (!intersect(ray, &hit, tc)) return {};
            if (pass_ == Pass::Normal) return {hit.ns.x, hit.ns.y, hit.ns.z};
            if (!hit.material) {
                ray = hit.spawn_ray(ray.d);
                continue;
            }
            return hit.material->albedo(hit);
        }
        return {};
    }

    bool signed_values() const override { return pass_ == Pass::Normal; }

private:
    Pass pass_;
};

} // namespace illum
