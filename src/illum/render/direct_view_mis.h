// A point y on an area light seen directly from the lens is found two ways when volpath runs with light
// tracing (volpath_caustics.h): by a camera ray that hits it, and by light tracing's connection of a
// photon's origin to the lens (s = 1, t = 1). A tiny light is seen almost only by the second, a large one
// best by the first, so the two are weighed by the power heuristic (Veach 1997 §10.2) on their densities
// per unit area at y, each for one sample over the whole film (light tracing traces as many particles as
// the camera takes samples):
//   p_camera = p_ω(lens → y) |cos θ_y| / r²  (the camera's directional density, camera_importance.h),
//   p_light  = P(light) p_A(y)               (light selection by power, then sample_le's position).
#pragma once

#include "illum/render/scene.h"

namespace illum {

inline float direct_view_weight(const Scene& scene, const Light& light, Point3f y, Normal3f n_y,
                                Point3f p_lens, float time, bool for_camera) {
    Vector3f d = y - p_lens;
    float r2 = length_squared(d);
    if (!(r2 > 0)) return for_camera ? 1.0f : 0.0f;
    Vector3f w = d / std::sqrt(r2);
    SurfaceHit at_y;
    at_y.p = y;
    at_y.n = n_y;
    at_y.time = time; // a moving light's density is that of its pose then
    float p_camera = scene.camera->pdf_we(Ray{p_lens, w}).dir.value * std::abs(dot(w, n_y)) / r2;
    float p_light = scene.light_sampler.pmf(&light) * light.pdf_le_position(at_y).value;
    // A film position outside the film: light tracing cannot splat there, so the camera ray counts alone.
    if (!(p_camera > 0)) return for_camera ? 1.0f : 0.0f;
    float a = for_camera ? p_camera : p_light, b = for_camera ? p_light : p_camera;
    if (std::isinf(a * a)) return 1;
    return a * a + b * b > 0 ? a * a / (a * a + b * b) : 0.0f;
}

} // namespace illum
