// Sampling kernels: ns per get_2d for each sampler, per Distribution1D sample on 1M entries, per AliasTable
// sample, per cosine-weighted hemisphere direction.
#include <benchmark/benchmark.h>

#include <vector>

#include "illum/math/distribution.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/render/sampler.h"

namespace illum {
namespace {

// One pixel sample (start_pixel_sample) followed by 8 get_2d calls, as a path of a few bounces would use;
// items = get_2d calls, so the reported time per item includes 1/8 of the per-sample setup.
void BM_SamplerGet2D(benchmark::State& state) {
    Sampler s(SamplerKind(state.range(0)), 64, 1);
    int pixel = 0;
    for (auto _ : state) {
        s.start_pixel_sample({pixel & 511, pixel >> 9}, pixel & 63);
        ++pixel;
        for (int d = 0; d < 8; ++d) benchmark::DoNotOptimize(s.get_2d());
    }
    state.SetItemsProcessed(state.iterations() * 8);
    state.SetLabel(std::string(sampler_kind_name(SamplerKind(state.range(0)))));
}
BENCHMARK(BM_SamplerGet2D)->Arg(int(SamplerKind::independent))->Arg(int(SamplerKind::sobol));

std::vector<float> million_weights() {
    std::vector<float> w(1 << 20);
    PCG32 rng(1);
    for (auto& x : w) x = rng.uniform_float() * rng.uniform_float();
    return w;
}

void BM_Distribution1DSampleContinuous(benchmark::State& state) {
    static const Distribution1D d(million_weights());
    PCG32 rng(2);
    for (auto _ : state) {
        float pdf;
        benchmark::DoNotOptimize(d.sample_continuous(rng.uniform_float(), &pdf));
        benchmark::DoNotOptimize(pdf);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Distribution1DSampleContinuous);

void BM_AliasTableSample(benchmark::State& state) {
    static const AliasTable t(million_weights());
    PCG32 rng(3);
    for (auto _ : state) {
        float pmf;
        benchmark::DoNotOptimize(t.sample(rng.uniform_float(), &pmf));
        benchmark::DoNotOptimize(pmf);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_AliasTableSample);

void BM_PCG32UniformFloat(benchmark::State& state) {
    PCG32 rng(4);
    for (auto _ : state) benchmark::DoNotOptimize(rng.uniform_float());
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PCG32UniformFloat);

// Random points, so that the concentric map's choice of wedge is as unpredictable as in a path tracer.
void BM_SampleCosineHemisphere(benchmark::State& state) {
    PCG32 rng(5);
    std::vector<Point2f> u(4096);
    for (auto& p : u) p = {rng.uniform_float(), rng.uniform_float()};
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(sample_cosine_hemisphere(u[i++ & 4095]));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SampleCosineHemisphere);

} // namespace
} // namespace illum
