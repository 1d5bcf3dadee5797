// Whole spheres as Embree's native sphere points against the same spheres as user geometry intersected
// in object space (AnalyticShape): closest hits with the hit filled in, and shadow rays, one thread, on
// 1000 random spheres hit by random rays. What this measures decided that scenes use user geometry only
// (Accelerator::add_shape).
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/sphere.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

std::unique_ptr<Accelerator> sphere_field(bool native) {
    auto acc = std::make_unique<Accelerator>();
    PCG32 rng(1);
    for (int i = 0; i < 1000; ++i) {
        Point3f c{10 * rng.uniform_float(), 10 * rng.uniform_float(), 10 * rng.uniform_float()};
        float r = 0.1f + 0.3f * rng.uniform_float();
        acc->add_shape(std::make_unique<SphereShape>(c, r, false), nullptr, nullptr, native);
    }
    acc->commit();
    return acc;
}

std::vector<Ray> random_rays(int n) {
    PCG32 rng(2);
    std::vector<Ray> rays(n);
    for (Ray& r : rays) {
        r.o = {10 * rng.uniform_float(), 10 * rng.uniform_float(), 10 * rng.uniform_float()};
        r.d = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        r.tmax = kInfinity;
    }
    return rays;
}

void BM_SphereClosestHit(benchmark::State& state) {
    auto acc = sphere_field(state.range(0) != 0);
    auto rays = random_rays(1 << 16);
    std::size_t hits = 0;
    for (auto _ : state) {
        for (const Ray& r : rays) {
            SurfaceHit h;
            hits += acc->intersect(r, &h);
        }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
    state.SetLabel(state.range(0) ? "native sphere point" : "user geometry");
}
BENCHMARK(BM_SphereClosestHit)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_SphereShadowRay(benchmark::State& state) {
    auto acc = sphere_field(state.range(0) != 0);
    auto rays = random_rays(1 << 16);
    std::size_t blocked = 0;
    for (auto _ : state)
        for (Ray r : rays) {
            r.tmax = 3;
            blocked += acc->occluded(r);
        }
    benchmark::DoNotOptimize(blocked);
    state.SetItemsProcessed(state.iterations() * std::int64_t(rays.size()));
    state.SetLabel(state.range(0) ? "native sphere point" : "user geometry");
}
BENCHMARK(BM_SphereShadowRay)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace illum
