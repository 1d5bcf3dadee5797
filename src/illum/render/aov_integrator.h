// Debug passes: the albedo (the first hit's material reflectance) and the shading normal (world space,
// components in [-1, 1]) of the first surface seen. Not radiance: the film's radiance channels carry the
// value unchanged (film_value(), the one place where a debug value enters the film).
#pragma once

#include "illum/render/integrator.h"

namespace illum {

class AovIntegrator final : public Integrator {
public:
    enum class Pass { Albedo, Normal };
    AovIntegrator(const Scene& scene, Pass pass) : Integrator(scene), pass_(pass) {}

    Radiance3 estimate(const Ray& camera_ray, ThreadContext& tc) const override {
        return film_value(value(camera_ray, tc));
    }
    bool starts_at_camera_hit() const override { return true; }
    // The pass's value at the first surface along the ray (zero where there is none).
    Color3 value(const Ray& camera_ray, ThreadContext& tc) const {
        Ray ray = camera_ray;
        for (int i = 0; i < 64; ++i) {
            SurfaceHit hit;
            if (!intersect(ray, &hit, tc)) return {};
            if (pass_ == Pass::Normal) {
                // The shading normal the BSDF sees: with the material's normal or bump map applied.
                if (hit.material && hit.material->has_surface_detail) apply_surface_detail(hit);
                return {hit.ns.x, hit.ns.y, hit.ns.z};
            }
            if (!hit.material) {
                ray = hit.spawn_ray(ray.d);
                continue;
            }
            return hit.material->albedo(hit);
        }
        return {};
    }

    bool signed_values() const override { return pass_ == Pass::Normal; }
    bool radiometric() const override { return false; }

private:
    // The film stores radiance; a debug value goes into its three channels as it is.
    static Radiance3 film_value(Color3 v) { return Radiance3(SampledSpectrum(v)); }
    Pass pass_;
};

} // namespace illum
