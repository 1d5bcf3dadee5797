// Whole-render throughput on the built-in Cornell box: Embree's raw closest-hit rate for incoherent
// rays (the ceiling), and the path tracer's rays/s and samples/s on the same scene and thread count.
#include <benchmark/benchmark.h>

#include <memory>
#include <thread>

#include "illum/render/ray_benchmark.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/builtin/builtin.h"

namespace illum {
namespace {

const Scene& cornell_box(int resolution) {
    static std::unique_ptr<Scene> scene;
    static int res = 0;
    if (!scene || res != resolution) {
        SceneDesc desc = builtin_cornell_box();
        desc.set_film_resolution(resolution, resolution);
        scene = build_scene(desc);
        res = resolution;
    }
    return *scene;
}

int threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

void BM_EmbreeIncoherentClosestHit(benchmark::State& state) {
    const Scene& scene = cornell_box(256);
    const int nthreads = int(state.range(0));
    std::uint64_t rays = 0;
    double seconds = 0;
    for (auto _ : state) {
        RayRate r = measure_incoherent_rays(scene, 1'000'000, nthreads);
        rays += r.rays;
        seconds += r.seconds;
        state.SetIterationTime(r.seconds);
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays) / seconds);
    state.counters["threads"] = nthreads;
}
BENCHMARK(BM_EmbreeIncoherentClosestHit)
    ->Arg(1)
    ->Arg(threads())
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_PathTracerCornellBox(benchmark::State& state) {
    const Scene& scene = cornell_box(256);
    const int nthreads = int(state.range(0));
    auto integrator = make_integrator("path", scene, scene.request.max_depth);
    RenderOptions opt;
    opt.spp = 8;
    opt.threads = nthreads;
    opt.quiet = true;
    std::uint64_t rays = 0, samples = 0;
    double seconds = 0;
    for (auto _ : state) {
        RenderResult r = render(scene, *integrator, opt);
        rays += r.rays;
        samples += r.samples;
        seconds += r.seconds;
        state.SetIterationTime(r.seconds);
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays) / seconds);
    state.counters["samples/s"] = benchmark::Counter(double(samples) / seconds);
    state.counters["threads"] = nthreads;
}
BENCHMARK(BM_PathTracerCornellBox)->Arg(1)->Arg(threads())->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace
} // namespace illum
