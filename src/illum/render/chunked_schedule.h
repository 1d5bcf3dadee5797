// The deterministic schedule of the integrators that splat (lightpath, bdpt): the sequence of chunks
// g = sample index · chunks_per_pass + pixel chunk (kChunkPixels pixels at one sample index) is traced in
// waves of kWaveChunks chunks in parallel, each chunk into its own output; the outputs are then applied in
// chunk order by one task, while the next wave is traced. What a chunk adds to the film therefore does not
// depend on the thread count, and the serial part overlaps the parallel one.
#pragma once

#include <algorithm>
#include <cstddef>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <oneapi/tbb/task_group.h>
#include <vector>

#include "illum/render/renderer.h"
#include "illum/util/progress.h"

namespace illum {

// 256 pixels a chunk: a wave's outputs (estimates and splats of 64 chunks, two waves held) take about 2 MB
// instead of the 10 MB of 1024-pixel chunks, for the same time (BDPT on the Cornell box and veach-bidir:
// paired wall-time ratios 1.009 and 0.998; peak memory 35.9 → 26.9 and 34.9 → 25.9 MiB). The chunk
// size does not change the image: the film receives the same additions in the same order.
inline constexpr std::size_t kChunkPixels = 256;
inline constexpr std::size_t kWaveChunks = 64;

// Runs items [0, n) of a sequence of work in waves of kWaveChunks: trace(out, k) fills item k's output in
// parallel; apply(out) is called on the outputs in item order by one task, while the next wave is traced.
template <class Output, class Trace, class Apply>
void run_waves(tbb::task_arena& arena, std::size_t n, Trace&& trace, Apply&& apply) {
    struct Wave {
        std::vector<Output> outputs = std::vector<Output>(kWaveChunks);
        std::size_t chunks = 0;
    };
    Wave waves[2];
    auto apply_wave = [&](Wave& wv) {
        for (std::size_t k = 0; k < wv.chunks; ++k) apply(wv.outputs[k]);
        wv.chunks = 0;
    };
    int cur = 0;
    for (std::size_t first = 0; first < n; first += kWaveChunks, cur = 1 - cur) {
        Wave& wv = waves[cur];
        wv.chunks = std::min<std::size_t>(kWaveChunks, n - first);
        arena.execute([&] {
            tbb::task_group previous;
            previous.run([&] { apply_wave(waves[1 - cur]); });
            tbb::parallel_for(std::size_t(0), wv.chunks,
                              [&](std::size_t k) { trace(wv.outputs[k], first + k); });
            previous.wait();
        });
    }
    apply_wave(waves[1 - cur]);
}

// trace(out, sample, p0, p1) traces pixels [p0, p1) at one (global) sample index into `out` (cleared by
// it); apply(out) adds an output to the film; snapshot(k) is the image after k passes, for a preview. Runs
// this process's share of options.spp passes, or whole passes until options.time_budget (run_passes);
// returns the passes taken. `progress` counts pixel samples.
template <class Output, class Trace, class Apply, class Snapshot>
int run_chunked_schedule(const RenderOptions& options, std::size_t pixels, tbb::task_arena& arena,
                         Progress& progress, Trace&& trace, Apply&& apply, Snapshot&& snapshot) {
    const std::size_t chunks_per_pass = (pixels + kChunkPixels - 1) / kChunkPixels;
    const SampleShare share = sample_share(options.group);
    // This process's passes k0..k1-1 are its chunks [k0 · chunks_per_pass, k1 · chunks_per_pass).
    int passes = run_passes(
        options, progress,
        [&](int k0, int k1) {
            const std::size_t g0 = std::size_t(k0) * chunks_per_pass;
            run_waves<Output>(
                arena, std::size_t(k1 - k0) * chunks_per_pass,
                [&](Output& out, std::size_t k) {
                    const std::size_t g = g0 + k;
                    const std::size_t p0 = (g % chunks_per_pass) * kChunkPixels,
                                      p1 = std::min(pixels, p0 + kChunkPixels);
                    trace(out, share.index(int(g / chunks_per_pass)), p0, p1);
                    progress.add(p1 - p0);
                },
                apply);
        },
        snapshot);
    progress.finish();
    return passes;
}

} // namespace illum
