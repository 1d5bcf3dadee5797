// ns per Material::bsdf() at a hit: what shading costs before any reflection is evaluated. Constant
// materials share one BxDF; textured ones evaluate their textures and place the model in the arena.
#include <benchmark/benchmark.h>

#include <string>

#include "illum/render/scene.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"

namespace illum {
namespace {

std::unique_ptr<Scene> material_scene(const std::string& material) {
    std::string text = R"(Camera "perspective"
Film "rgb" "integer xresolution" [4] "integer yresolution" [4]
WorldBegin
Texture "checks" "spectrum" "checkerboard" "float uscale" [16] "float vscale" [16] "rgb tex1" [0.8 0.2 0.1] "rgb tex2" [0.1 0.3 0.7]
Texture "fchecks" "float" "checkerboard" "float uscale" [8] "float vscale" [8] "float tex1" [0.05] "float tex2" [0.4]
)" + material + "\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n";
    return build_scene(parse_pbrt_string(text, "<bench>", "."));
}

void BM_MaterialBsdf(benchmark::State& state, std::string material) {
    auto scene = material_scene(material);
    const Material* m = scene->materials.front().get(); // the last one is the default material
    ScratchArena arena;
    SurfaceHit hit;
    hit.n = hit.ns = Normal3f(0, 0, 1);
    hit.dpdu = Vector3f(1, 0, 0);
    hit.wo = Vector3f(0, 0, 1);
    SampledWavelengths lambda = SampledWavelengths::rgb_mode();
    int i = 0;
    for (auto _ : state) {
        hit.uv = Point2f((i & 63) / 64.0f, ((i >> 6) & 63) / 64.0f);
        BSDF b = m->bsdf(hit, lambda, arena);
        benchmark::DoNotOptimize(b);
        arena.reset();
        ++i;
    }
}
BENCHMARK_CAPTURE(BM_MaterialBsdf, diffuse_constant, R"(Material "diffuse" "rgb reflectance" [0.5 0.5 0.5])");
BENCHMARK_CAPTURE(BM_MaterialBsdf, diffuse_textured, R"(Material "diffuse" "texture reflectance" "checks")");
BENCHMARK_CAPTURE(
    BM_MaterialBsdf, ward_textured,
    R"(Material "ward" "texture rho_d" "checks" "rgb rho_s" [0.2 0.2 0.2] "texture alpha" "fchecks")");
BENCHMARK_CAPTURE(BM_MaterialBsdf, phong_textured,
                  R"(Material "phong" "texture kd" "checks" "rgb ks" [0.3 0.3 0.3] "float exponent" [50])");
BENCHMARK_CAPTURE(
    BM_MaterialBsdf, coated_diffuse_textured,
    R"(Material "coated-diffuse" "texture reflectance" "checks" "texture roughness" "fchecks")");

} // namespace
} // namespace illum
