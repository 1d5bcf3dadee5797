// Parsing the largest shared scene (coffee: pbrt text plus 20 binary PLY meshes, ~7 MB), reporting
// bytes processed so the output shows MB/s. The shared folder comes from the environment variable
// ILLUM_SHARED_DIR, falling back to ../shared (relative to the working directory).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "illum/scene/pbrt/parser.h"
#include "illum/geometry/ply.h"

namespace {

namespace fs = std::filesystem;

std::string shared_dir() {
    const char* env = std::getenv("ILLUM_SHARED_DIR");
    return env && *env ? std::string(env) : std::string("../shared");
}

void BM_PbrtParseCoffee(benchmark::State& state) {
    const std::string path = (fs::path(shared_dir()) / "scenes/coffee/scene-v4.pbrt").string();
    if (!fs::exists(path)) {
        state.SkipWithError(("scene absent: " + path + " (set ILLUM_SHARED_DIR)").c_str());
        return;
    }
    int64_t bytes = 0;
    size_t triangles = 0;
    for (auto _ : state) {
        illum::SceneDesc scene = illum::parse_pbrt_file(path);
        bytes += int64_t(fs::file_size(path));
        for (const auto& shape : scene.shapes) {
            if (shape.type != "plymesh") continue;
            const std::string file = shape.params.get_string("filename", "");
            illum::TriangleMeshData mesh = illum::read_ply(file);
            triangles += mesh.indices.size() / 3;
            bytes += int64_t(fs::file_size(file));
            benchmark::DoNotOptimize(mesh.positions.data());
        }
    }
    state.SetBytesProcessed(bytes);
    state.counters["triangles"] = benchmark::Counter(double(triangles), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_PbrtParseCoffee)->Unit(benchmark::kMillisecond);

void BM_PbrtParseCornellText(benchmark::State& state) {
    const std::string path = (fs::path(shared_dir()) / "scenes/cornell-box/scene-v4.pbrt").string();
    if (!fs::exists(path)) {
        state.SkipWithError(("scene absent: " + path + " (set ILLUM_SHARED_DIR)").c_str());
        return;
    }
    for (auto _ : state) {
        illum::SceneDesc scene = illum::parse_pbrt_file(path);
        benchmark::DoNotOptimize(scene.shapes.data());
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(fs::file_size(path)));
}
BENCHMARK(BM_PbrtParseCornellText)->Unit(benchmark::kMicrosecond);

} // namespace
