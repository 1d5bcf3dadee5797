// ns per f() and per sample() call of each reflection model, at its default parameters (MERL uses a
// synthetic GGX table).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "illum/bsdf/registry.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

std::map<std::string, std::string> bench_params(const std::string& model) {
    if (model == "merl") return {{"file", "synthetic:0.3"}};
    return {};
}

struct Directions {
    std::vector<Vector3f> wo, wi;
    std::vector<float> u;
    Directions() {
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<float> U(0, 0.999f);
        for (int i = 0; i < 1024; ++i) {
            wo.push_back(sample_cosine_hemisphere({U(rng), U(rng)}));
            wi.push_back(sample_cosine_hemisphere({U(rng), U(rng)}));
            u.push_back(U(rng));
        }
    }
};
const Directions& dirs() {
    static Directions d;
    return d;
}

void BM_f(benchmark::State& state, std::string model) {
    auto bxdf = make_bxdf(model, bench_params(model));
    const auto& d = dirs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bxdf->f(d.wo[i & 1023], d.wi[i & 1023], TransportMode::Radiance));
        ++i;
    }
}

void BM_sample(benchmark::State& state, std::string model) {
    auto bxdf = make_bxdf(model, bench_params(model));
    const auto& d = dirs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bxdf->sample(d.wo[i & 1023], d.u[i & 1023],
                                              {d.u[(i + 1) & 1023], d.u[(i + 2) & 1023]},
                                              TransportMode::Radiance));
        ++i;
    }
}

int register_all() {
    for (const auto& m : bxdf_models()) {
        benchmark::RegisterBenchmark(("bsdf_f/" + m.name).c_str(), BM_f, m.name);
        benchmark::RegisterBenchmark(("bsdf_sample/" + m.name).c_str(), BM_sample, m.name);
    }
    return 0;
}
const int registered = register_all();

} // namespace
} // namespace illum
