// `illum bench`: on the built-in Cornell box, the raw Embree closest-hit rate for incoherent rays, the
// path tracer's rays/s and samples/s at the same thread count, and their ratio. Each round measures the
// two back to back and forms its own ratio, so a machine whose speed drifts (a shared virtual machine) moves
// both sides of a ratio together; the figures are those of the round with the median ratio.
#include <algorithm>
#include <fmt/core.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "commands.h"
#include "illum/render/ray_benchmark.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/builtin/builtin.h"
#include "scene_loading.h"

namespace illum::cli {

namespace {

struct BenchArgs {
    std::string scene;
    int threads = 0;
    int spp = 16;
    std::string resolution = "512x512";
    std::uint64_t rays = 4'000'000;
    int rounds = 3;
    bool json = false;
    bool spectral = false;
};

void run(const BenchArgs& args) {
    SceneDesc desc = load_scene_desc(args.scene);
    auto [w, h] = parse_resolution(args.resolution);
    desc.set_film_resolution(w, h);
    auto scene = build_scene(desc);
    int threads = args.threads > 0 ? args.threads : int(std::max(1u, std::thread::hardware_concurrency()));

    // Warm up Embree's caches and the thread pool, then measure.
    measure_incoherent_rays(*scene, args.rays / 10, threads);
    auto integrator = make_integrator("path", *scene, scene->request.max_depth);
    RenderOptions opt;
    opt.spp = args.spp;
    opt.threads = threads;
    opt.quiet = true;
    struct Round {
        RayRate raw;
        RenderResult path;
        double ratio() const { return (path.rays / path.seconds) / raw.rays_per_second(); }
    };
    std::vector<Round> rounds;
    for (int i = 0; i < args.rounds; ++i) {
        Round round{measure_incoherent_rays(*scene, args.rays, threads), {}};
        round.path = render(*scene, *integrator, opt);
        rounds.push_back(std::move(round));
    }
    // The round with the median ratio gives every figure, so they belong together.
    std::vector<double> ratios;
    for (const Round& round : rounds) ratios.push_back(round.ratio());
    std::vector<std::size_t> order(rounds.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return ratios[a] < ratios[b]; });
    const Round& median = rounds[order[order.size() / 2]];
    const RayRate& raw = median.raw;
    const RenderResult& r = median.path;
    double path_rays = r.rays / r.seconds, samples = r.samples / r.seconds;
    double ratio = median.ratio();
    const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
    // Spectral mode's cost per camera sample against RGB mode's, the same render at four wavelengths.
    double spectral_samples = 0, spectral_rays_per_sample = 0;
    if (args.spectral) {
        opt.spectral = true;
        RenderResult s = render(*scene, *integrator, opt);
        spectral_samples = s.samples / s.seconds;
        spectral_rays_per_sample = double(s.rays) / s.samples;
    }

    if (args.json) {
        nlohmann::json j = {{"scene", args.scene.empty() ? "<built-in cornell-box>" : args.scene},
                            {"threads", threads},
                            {"resolution", {w, h}},
                            {"spp", args.spp},
                            {"embree_incoherent_rays_per_second", raw.rays_per_second()},
                            {"path_rays_per_second", path_rays},
                            {"path_samples_per_second", samples},
                            {"path_rays_per_sample", double(r.rays) / r.samples},
                            {"ratio", ratio},
                            {"rounds", args.rounds},
                            {"ratios", ratios},
                            {"version", ILLUM_VERSION}};
        if (args.spectral) {
            j["spectral_samples_per_second"] = spectral_samples;
            j["spectral_rays_per_sample"] = spectral_rays_per_sample;
            j["spectral_cost_per_sample"] = samples / spectral_samples;
        }
        fmt::print("{}\n", j.dump(2));
        return;
    }
    fmt::print("scene: {} ({}x{}, {} spp, {} threads)\n",
               args.scene.empty() ? "built-in Cornell box" : args.scene, w, h, args.spp, threads);
    fmt::print("  Embree closest hit, incoherent rays : {:10.2f} Mrays/s ({} rays in {:.3f} s)\n",
               raw.rays_per_second() / 1e6, raw.rays, raw.seconds);
    fmt::print(
        "  path tracer                          : {:10.2f} Mrays/s, {:.2f} Msamples/s ({:.2f} rays/sample)\n",
        path_rays / 1e6, samples / 1e6, double(r.rays) / r.samples);
    fmt::print("  path tracer / raw Embree             : {:10.1f} % (median of {} rounds: {:.1f}-{:.1f} %)\n",
               100 * ratio, args.rounds, 100 * *low, 100 * *high);
    if (args.spectral)
        fmt::print(
            "  spectral mode                        : {:10.2f} Msamples/s ({:.2f} rays/sample): {:.3f}x "
            "RGB mode's time per sample\n",
            spectral_samples / 1e6, spectral_rays_per_sample, samples / spectral_samples);
}

} // namespace

void add_bench_command(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd =
        app.add_subcommand("bench", "Measure ray and sample throughput (default: the built-in Cornell box)");
    cmd->add_option("scene", args->scene, "Scene file (.pbrt); omit for the built-in Cornell box");
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(positive_integer());
    cmd->add_option("--spp", args->spp, "Samples per pixel of the path-traced render")
        ->check(positive_integer());
    cmd->add_option("--resolution", args->resolution, "Film resolution WIDTHxHEIGHT");
    cmd->add_option("--rays", args->rays, "Number of incoherent rays for the raw Embree rate")
        ->check(positive_integer());
    cmd->add_option("--rounds", args->rounds,
                    "Rounds of both measurements; the figures are the round with the median ratio")
        ->check(positive_integer());
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    cmd->add_flag("--spectral", args->spectral,
                  "Also render in spectral mode and report its cost per camera sample against RGB mode's");
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli
