// Throughput measurements shared by `illum bench` and bench/: the raw Embree closest-hit rate for
// incoherent rays (the ceiling a renderer can reach), and the path tracer's rates on the same scene.
#pragma once

#include <cstdint>

#include "illum/render/renderer.h"
#include "illum/render/scene.h"

namespace illum {

struct RayRate {
    std::uint64_t rays = 0;
    double seconds = 0;
    double rays_per_second() const { return seconds > 0 ? rays / seconds : 0; }
};

// Traces `count` rays with origins uniform in the scene's bounds and directions uniform on the sphere
// (precomputed, fixed seed), closest hit only, on `threads` threads.
RayRate measure_incoherent_rays(const Scene& scene, std::uint64_t count, int threads);

} // namespace illum
