// `illum photons SCENE -o photons.ply [--count N]`: the photons of one SPPM iteration as a PLY point cloud,
// one point per surface a photon reaches: where it lands, the direction it travels and the power it carries
// (β / N, film RGB, watts), and after how many scattering events (0: straight from a light). A point-cloud
// viewer then shows what the emitters cast: the direct footprint of each light, caustics, colour bleeding.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <memory>
#include <oneapi/tbb/parallel_for.h>
#include <vector>

#include "commands.h"
#include "illum/math/rng.h"
#include "illum/render/photon_tracer.h"
#include "illum/render/render_arena.h"
#include "illum/render/sppm_integrator.h"
#include "illum/scene/build.h"
#include "illum/util/error.h"
#include "scene_loading.h"

namespace illum::cli {

namespace {

struct PhotonsArgs {
    std::string scene, output;
    long long count = 0; // 0: the scene's photonsperiteration (or the pixel count)
    int max_depth = -2;  // -2: the scene's
    std::uint64_t seed = 0;
    bool quiet = false;
};

// One PLY vertex, in file order.
struct PhotonPoint {
    float x, y, z, dx, dy, dz, r, g, b;
    std::uint8_t bounce;
};
constexpr std::size_t kPointBytes = 9 * sizeof(float) + 1;

void write_ply(const std::string& path, const std::vector<PhotonPoint>& points) {
    std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
        out << "ply\nformat binary_little_endian 1.0\n"
            << "comment illum photons: position, direction of travel, power [W] (film RGB), bounce\n"
            << "element vertex " << points.size() << "\n"
            << "property float x\nproperty float y\nproperty float z\n"
            << "property float dx\nproperty float dy\nproperty float dz\n"
            << "property float red\nproperty float green\nproperty float blue\n"
            << "property uchar bounce\nend_header\n";
        std::vector<char> buf(kPointBytes * 4096);
        for (std::size_t i = 0; i < points.size();) {
            std::size_t n = std::min<std::size_t>(4096, points.size() - i);
            for (std::size_t j = 0; j < n; ++j) {
                const PhotonPoint& p = points[i + j];
                std::memcpy(&buf[j * kPointBytes], &p.x, 9 * sizeof(float)); // x86/ARM: little-endian floats
                buf[j * kPointBytes + 9 * sizeof(float)] = char(p.bounce);
            }
            out.write(buf.data(), std::streamsize(n * kPointBytes));
            i += n;
        }
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
    }
    std::filesystem::rename(tmp, path);
}

void run(const PhotonsArgs& args) {
    if (std::filesystem::path(args.output).extension() != ".ply")
        throw Error(fmt::format("cannot write \"{}\": the photons are written as .ply", args.output));
    SceneDesc desc = load_scene_desc(args.scene);
    std::unique_ptr<Scene> scene = build_scene(desc);
    if (!args.quiet) print_warnings(scene->warnings);
    if (scene->lights.empty()) throw Error("the scene has no lights");
    const RenderRequest& rq = scene->request;
    int max_depth = args.max_depth == -2 ? rq.max_depth : args.max_depth;
    if (max_depth < 0) max_depth = 5;
    SPPMIntegrator sppm(*scene, SppmSettings{max_depth, rq.sppm_photons_per_iteration, rq.sppm_radius,
                                             std::uint64_t(rq.sppm_seed)});
    const std::uint64_t n = std::uint64_t(args.count > 0 ? args.count : sppm.photons_per_iteration());
    // The photon streams of the renderer's first iteration (sppm_integrator.cpp seeds them the same way).
    PhotonTracer tracer(*scene, max_depth);
    const Sampler prototype(SamplerKind::sobol, 1, hash(args.seed, sppm.settings().seed));
    const float share = float(1.0 / double(n));

    // Chunks of photons traced in parallel, concatenated in photon order.
    constexpr std::uint64_t kChunk = 4096;
    const std::size_t chunks = std::size_t((n + kChunk - 1) / kChunk);
    std::vector<std::vector<PhotonPoint>> parts(chunks);
    // In a render's arena, as the renderer traces them (denormals flushed: render_arena.h).
    const int threads = tbb::this_task_arena::max_concurrency();
    RenderArena render_arena(threads);
    render_arena.execute([&] {
        tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
            Sampler sampler = prototype;
            ScratchArena arena;
            SampledWavelengths lambda = SampledWavelengths::rgb_mode();
            for (std::uint64_t i = c * kChunk; i < std::min(n, (c + 1) * kChunk); ++i)
                tracer.trace(i, lambda, sampler, arena, [&](const PhotonArrival& a) {
                    Color3 power = scene->sensor.to_rgb(Radiance3(a.beta * share), a.lambda); // film RGB
                    parts[c].push_back({a.hit.p.x, a.hit.p.y, a.hit.p.z, -a.wi.x, -a.wi.y, -a.wi.z, power.r,
                                        power.g, power.b, std::uint8_t(std::min(a.bounce, 255))});
                });
        });
    });
    std::vector<PhotonPoint> points;
    double emitted[3] = {0, 0, 0};
    for (const auto& p : parts) points.insert(points.end(), p.begin(), p.end());
    for (const PhotonPoint& p : points)
        if (p.bounce == 0) {
            emitted[0] += p.r;
            emitted[1] += p.g;
            emitted[2] += p.b;
        }
    write_ply(args.output, points);
    if (!args.quiet) {
        Color3 lights;
        for (const auto& l : scene->lights) lights += l->power().rgb();
        fmt::print(stderr, "{} photons, {} surface hits written to {}\n", n, points.size(), args.output);
        fmt::print(stderr,
                   "power reaching surfaces directly: {:.4g} {:.4g} {:.4g} W; the lights emit {:.4g} {:.4g} "
                   "{:.4g} W\n",
                   emitted[0], emitted[1], emitted[2], lights.r, lights.g, lights.b);
    }
}

} // namespace

void add_photons_command(CLI::App& app) {
    auto args = std::make_shared<PhotonsArgs>();
    CLI::App* cmd =
        app.add_subcommand("photons", "Write the photons of one SPPM iteration as a PLY point cloud");
    cmd->add_option("scene", args->scene, "Scene file (.pbrt)")->required();
    cmd->add_option("-o,--output", args->output, "Output point cloud (.ply)")->required();
    cmd->add_option("--count", args->count,
                    "Photons to emit (default: the scene's photonsperiteration, or the pixel count)")
        ->check(positive_integer());
    cmd->add_option("--max-depth", args->max_depth, "Surface hits per photon (default: the scene's maxdepth)")
        ->check(CLI::Range(0, 100000));
    cmd->add_option("--seed", args->seed, "Seed (as illum render's)");
    cmd->add_flag("-q,--quiet", args->quiet, "No warnings or summary");
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli
