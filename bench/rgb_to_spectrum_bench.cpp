// RGB -> sigmoid polynomial: ns per RGBColorSpace::to_polynomial (the table lookup: argmax, a binary search
// of the z grid, trilinear interpolation of 8 entries), on random colours (mostly cache misses in the
// 9.4 MB table; half of them through the complement) and on one texel's neighbourhood (cache hits); and per
// evaluation of the polynomial.
#include <benchmark/benchmark.h>

#include <vector>

#include "illum/math/rng.h"
#include "illum/radiometry/color_space.h"

namespace illum {
namespace {

std::vector<Color3> colours(float spread) {
    std::vector<Color3> c(1 << 16);
    PCG32 rng(7);
    for (Color3& x : c)
        x = Color3(0.5f + spread * (rng.uniform_float() - 0.5f), 0.3f + spread * (rng.uniform_float() - 0.5f),
                   0.2f + spread * (rng.uniform_float() - 0.5f));
    return c;
}

void BM_ToPolynomial(benchmark::State& state) {
    static const std::vector<Color3> random = colours(1.0f), nearby = colours(0.01f);
    const std::vector<Color3>& c = state.range(0) ? nearby : random;
    const RGBColorSpace& cs = RGBColorSpace::srgb();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(cs.to_polynomial(c[i]));
        i = (i + 1) & (c.size() - 1);
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(state.range(0) ? "nearby colours" : "random colours");
}
BENCHMARK(BM_ToPolynomial)->Arg(0)->Arg(1);

void BM_EvaluatePolynomial(benchmark::State& state) {
    RGBSigmoidPolynomial p = RGBColorSpace::srgb().to_polynomial(Color3(0.7f, 0.2f, 0.1f));
    float lambda = 360;
    for (auto _ : state) {
        benchmark::DoNotOptimize(p(lambda));
        lambda = lambda < 830 ? lambda + 1.7f : 360;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluatePolynomial);

} // namespace
} // namespace illum
