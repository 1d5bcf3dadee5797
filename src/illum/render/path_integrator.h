// Unidirectional path tracing with next-event estimation and multiple importance sampling (Veach 1997;
// Pharr et al., PBR 4th ed. §13.4). At each non-specular vertex one light, picked by power, is sampled
// and the BSDF is sampled to continue the path; emission found by either strategy is weighted by the
// power heuristic. Russian roulette on the throughput ends paths without bias.
#pragma once

#include "illum/render/integrator.h"

namespace illum {

class PathIntegrator final : public Integrator {
public:
    // max_depth: the number of scattering events (0 shows emitters only); negative for unbounded.
    PathIntegrator(const Scene& scene, int max_depth) : Integrator(scene), max_depth_(max_depth) {}
    Radiance3 estimate(const Ray& camera_ray, ThreadContext& tc) const override {
        return radiance(camera_ray, tc);
    }
    Radiance3 radiance(Ray ray, ThreadContext& tc) const;
    bool starts_at_camera_hit() const override { return true; }

private:
    int max_depth_;
};

} // namespace illum
