#include "illum/render/ray_benchmark.h"

#include <chrono>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <vector>

#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/render/render_arena.h"

namespace illum {

RayRate measure_incoherent_rays(const Scene& scene, std::uint64_t count, int threads) {
    Bounds3f b = scene.accelerator.bounds();
    Vector3f ext = b.diagonal();
    std::vector<Ray> rays(count);
    PCG32 rng(7);
    for (auto& r : rays) {
        Point3f o{b.lo.x + ext.x * rng.uniform_float(), b.lo.y + ext.y * rng.uniform_float(),
                  b.lo.z + ext.z * rng.uniform_float()};
        float u0 = rng.uniform_float(), u1 = rng.uniform_float();
        r = Ray{o, sample_uniform_sphere({u0, u1}), kInfinity};
    }
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    RenderArena arena(threads);
    std::vector<float> t(count);
    auto start = std::chrono::steady_clock::now();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096), [&](const auto& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i)
                t[i] = scene.accelerator.intersect_distance(rays[i]);
        });
    });
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {count, seconds};
}

} // namespace illum
