// The samplers' cost per pixel sample as a path tracer draws it: start_pixel_sample, the pixel offset, the
// lens and wavelength, then per bounce a light choice (1D), a light point (2D), a lobe (1D), a direction
// (2D) and a roulette number (1D), five bounces: 2 + 2 + 1 + 5 x 7 = 40 numbers in 20 calls. Pixels of a
// 512 x 512 film at 16 spp, in scanline order, every sample of a pixel before the next pixel (the render
// loop's order). Items = pixel samples.
#include <benchmark/benchmark.h>

#include "illum/render/sampler.h"

namespace illum {
namespace {

void pixel_samples(benchmark::State& state, SamplerKind kind, SamplerSettings settings) {
    settings.resolution = {512, 512};
    Sampler s(kind, 16, 1, settings);
    uint32_t n = 0;
    for (auto _ : state) {
        const uint32_t pixel = (n >> 4) & ((1u << 18) - 1);
        s.start_pixel_sample({int(pixel & 511), int(pixel >> 9)}, int(n & 15));
        ++n;
        benchmark::DoNotOptimize(s.get_pixel_2d());
        benchmark::DoNotOptimize(s.get_2d());
        benchmark::DoNotOptimize(s.get_1d());
        for (int bounce = 0; bounce < 5; ++bounce) {
            benchmark::DoNotOptimize(s.get_1d());
            benchmark::DoNotOptimize(s.get_2d());
            benchmark::DoNotOptimize(s.get_1d());
            benchmark::DoNotOptimize(s.get_2d());
            benchmark::DoNotOptimize(s.get_1d());
        }
    }
    state.SetItemsProcessed(state.iterations());
}

SamplerSettings randomized(Randomization r) {
    SamplerSettings s;
    s.randomization = r;
    return s;
}

BENCHMARK_CAPTURE(pixel_samples, independent, SamplerKind::independent, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, sobol, SamplerKind::sobol, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, zsobol, SamplerKind::zsobol, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, zsobol_none, SamplerKind::zsobol, randomized(Randomization::none));
BENCHMARK_CAPTURE(pixel_samples, zsobol_permutedigits, SamplerKind::zsobol,
                  randomized(Randomization::permute_digits));
BENCHMARK_CAPTURE(pixel_samples, zsobol_owen, SamplerKind::zsobol, randomized(Randomization::owen));
BENCHMARK_CAPTURE(pixel_samples, paddedsobol, SamplerKind::paddedsobol, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, halton, SamplerKind::halton, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, halton_owen, SamplerKind::halton, randomized(Randomization::owen));
BENCHMARK_CAPTURE(pixel_samples, pmj02bn, SamplerKind::pmj02bn, SamplerSettings{});
BENCHMARK_CAPTURE(pixel_samples, stratified, SamplerKind::stratified, SamplerSettings{});

} // namespace
} // namespace illum
