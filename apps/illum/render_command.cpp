// `illum render [SCENE] [-o OUT.{exr,pfm,hdr,png}]...`: renders a pbrt-v4 scene, or the built-in Cornell
// box when no scene is named.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <unistd.h>

#include "commands.h"
#include "illum/image/image_io.h"
#include "illum/image/tonemap.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/util/error.h"
#include "mpi_run.h"
#include "preview_server.h"
#include "scene_loading.h"

namespace illum::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::vector<std::string> outputs;
    int spp = 0; // 0: the scene's
    double time = 0;
    int threads = 0;
    std::optional<std::uint64_t> seed; // none: the scene's (Sampler "seed", else Option "seed", else 0)
    std::string integrator;            // "": the scene's
    int max_depth = -2;                // -2: the scene's
    std::string sampler;
    std::string light_sampler; // "": the scene's
    std::string resolution;    // WxH
    std::string stats;
    std::string tonemap = "clamp";
    float exposure = 0;
    bool quiet = false;
    bool strict = false;
    bool spectral = false;
    std::string share; // "R/N": render rank R's share of an N-rank job alone
    std::string serve; // "HOST:PORT" or "PORT" of the live preview
    double serve_linger = 0;
    bool adaptive = false;
    double adaptive_threshold = 0;
    std::optional<int> adaptive_min_spp; // none: AdaptiveSettings' default
};

void check_output_folder_only(const std::string& path) {
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    if (dir.empty()) dir = ".";
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec) || access(dir.c_str(), W_OK) != 0)
        throw Error(
            fmt::format("cannot write \"{}\": folder \"{}\" is missing or not writable", path, dir.string()));
}

// Fails early, before any rendering, if an output cannot be created: the folder must exist and be
// writable. The image itself is written through a temporary file and a rename.
void check_output(const std::string& path) {
    if (!is_supported_output_extension(path)) {
        throw Error(
            fmt::format("cannot write \"{}\": unknown image extension \"{}\" (use .exr, .pfm, .hdr or .png)",
                        path, image_extension(path)));
    }
    check_output_folder_only(path);
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error(fmt::format("cannot write \"{}\": it is a directory", path));
}

// Where a run's time went, for the stats: reading and building the scene (every rank does it), the
// group's communication (its sums and broadcasts, including waiting for the slowest rank), the ranks.
struct RenderTimes {
    double setup_seconds = 0;
    double communication_seconds = 0;
    int ranks = 1;
};

void write_stats(const std::string& path, const RenderArgs& args, const Scene& scene, const RenderResult& r,
                 const std::string& integrator, std::uint64_t seed, const RenderTimes& times) {
    nlohmann::json j;
    j["version"] = ILLUM_VERSION;
    j["scene"] = args.scene.empty() ? "<built-in cornell-box>" : args.scene;
    j["integrator"] = integrator;
    j["resolution"] = {scene.width, scene.height};
    j["spp"] = r.spp;
    j["samples"] = r.samples;
    j["rays"] = r.rays;
    j["seconds"] = r.seconds;
    j["samples_per_second"] = r.seconds > 0 ? r.samples / r.seconds : 0.0;
    j["rays_per_second"] = r.seconds > 0 ? r.rays / r.seconds : 0.0;
    j["threads"] = r.threads;
    j["ranks"] = times.ranks;
    j["setup_seconds"] = times.setup_seconds;
    j["communication_seconds"] = times.communication_seconds;
    j["seed"] = seed;
    j["nonfinite_samples"] = r.nonfinite_samples;
    j["mode"] = args.spectral ? "spectral" : "rgb";
    j["color_space"] = std::string(scene.color_space->name());
    if (r.adaptive)
        j["adaptive"] = {{"min_spp", r.adaptive->min_spp},
                         {"max_spp", r.adaptive->max_spp},
                         {"rounds", r.adaptive->rounds},
                         {"level", r.adaptive->level},
                         {"threshold", args.adaptive_threshold}};
    std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp);
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
        out << j.dump(2) << "\n";
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
    }
    std::filesystem::rename(tmp, path);
}

// "R/N" of --share.
std::pair<int, int> parse_share(const std::string& s) {
    int r = -1, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &r, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || r < 0 ||
        r >= n)
        throw Error("--share \"" + s + "\" is not RANK/RANKS with 0 <= RANK < RANKS");
    return {r, n};
}

// Everything before the render: may fail on one rank of a job only (its node's copy of the scene), so the
// ranks agree on it before any of them starts (MpiRun::agree).
struct Prepared {
    std::unique_ptr<Scene> scene;
    std::unique_ptr<Integrator> integrator;
    std::string integrator_name;
    std::vector<std::string> outputs;
    WriteOptions write_options;
    RenderOptions options;
    std::optional<ServeAddress> serve;
};

Prepared prepare(const RenderArgs& args, bool lead, bool quiet) {
    Prepared p;
    auto tonemap = tonemap_from_string(args.tonemap);
    if (!tonemap)
        throw Error(fmt::format("unknown tone map \"{}\" (use clamp, reinhard or aces)", args.tonemap));
    // Only rank 0 writes, so only its outputs are checked (the folders may exist on its node alone).
    if (lead) {
        for (const auto& o : args.outputs) check_output(o);
        if (!args.stats.empty()) check_output_folder_only(args.stats);
    }

    SceneDesc desc = load_scene_desc(args.scene, args.strict);
    if (!args.resolution.empty()) {
        auto [w, h] = parse_resolution(args.resolution);
        desc.set_film_resolution(w, h);
    }
    BuildOptions build_options;
    build_options.strict = args.strict;
    p.scene = build_scene(desc, build_options);
    if (!quiet) print_warnings(p.scene->warnings);

    p.outputs = args.outputs;
    if (p.outputs.empty()) {
        std::string name = p.scene->request.output.empty() ? "illum.exr" : p.scene->request.output;
        if (!is_supported_output_extension(name))
            name = std::filesystem::path(name).replace_extension(".exr").string();
        // The film's filename is relative to where illum runs, as in pbrt.
        if (lead) check_output(name);
        p.outputs.push_back(name);
    }

    if (!args.light_sampler.empty()) p.scene->set_light_sampler(*parse_light_sampler(args.light_sampler));
    p.integrator_name = args.integrator.empty() ? p.scene->request.integrator : args.integrator;
    int max_depth = args.max_depth == -2 ? p.scene->request.max_depth : args.max_depth;
    p.integrator = make_integrator(p.integrator_name, *p.scene, max_depth);

    p.options.spp = args.spp > 0 ? args.spp : p.scene->request.spp;
    p.options.time_budget = args.time;
    p.options.threads = args.threads;
    p.options.seed = args.seed ? *args.seed : p.scene->request.scene_seed();
    p.options.sampler = args.sampler.empty() ? p.scene->request.sampler : args.sampler;
    p.options.sampler_settings = p.scene->request.sampler_settings;
    p.options.quiet = quiet;
    p.options.spectral = args.spectral;
    p.options.adaptive.enabled = args.adaptive || args.adaptive_threshold > 0 || args.adaptive_min_spp;
    p.options.adaptive.threshold = args.adaptive_threshold;
    if (args.adaptive_min_spp) p.options.adaptive.min_spp = *args.adaptive_min_spp;
    p.write_options.exposure_stops = args.exposure;
    p.write_options.tonemap = *tonemap;
    // EXR output as pbrt-v4 writes its film: half precision unless the film says "savefp16" false (also for
    // -o x.exr and the built-in scene), and a crop as the data window of the full display window.
    p.write_options.exr.half = p.scene->request.save_fp16;
    const PixelBounds bounds = p.scene->output_bounds();
    p.write_options.exr.display_width = p.scene->width;
    p.write_options.exr.display_height = p.scene->height;
    p.write_options.exr.x0 = bounds.x0;
    p.write_options.exr.y0 = bounds.y0;
    if (!args.serve.empty()) p.serve = parse_serve_address(args.serve);
    return p;
}

void run(const RenderArgs& args) {
    const auto start = std::chrono::steady_clock::now();
    RenderGroup* group = MpiRun::group();
    std::optional<SoloShare> solo;
    if (!args.share.empty()) {
        if (group) throw Error("--share renders one rank's share alone: it cannot be used under mpirun");
        auto [r, n] = parse_share(args.share);
        solo.emplace(r, n);
        group = &*solo;
    }
    const bool lead = !MpiRun::group() || MpiRun::rank() == 0;
    const bool quiet = args.quiet || !lead; // rank 0 speaks for the job

    Prepared p;
    std::string error;
    try {
        p = prepare(args, lead, quiet);
        p.options.group = group;
    } catch (const Error& e) {
        if (!MpiRun::group()) throw;
        error = e.what();
        if (error.empty()) error = "failed";
    }
    MpiRun::agree(error);
    const double setup_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // The live preview: rank 0's, of its own share in a job of several ranks.
    std::unique_ptr<PreviewServer> server;
    if (p.serve && lead) {
        const int total = p.options.time_budget > 0 ? 0 : sample_share(group).count(p.options.spp);
        server = std::make_unique<PreviewServer>(*p.serve, p.scene->width, p.scene->height, total);
        fmt::print(stderr, "preview: {}\n", server->url());
        p.options.preview = server.get();
    }

    RenderResult result = render(*p.scene, *p.integrator, p.options);
    if (!lead) return;
    if (result.nonfinite_samples > 0 && !args.quiet)
        fmt::print(stderr, "warning: {} samples were NaN, infinite or negative and were dropped\n",
                   result.nonfinite_samples);

    for (const auto& o : p.outputs) {
        write_image(result.image, o, p.write_options);
        if (!args.quiet) fmt::print(stderr, "wrote {}\n", o);
    }
    for (const auto& extra : result.extra_images) write_image(extra.image, extra.name);
    if (!result.extra_images.empty() && !args.quiet)
        fmt::print(stderr, "wrote {} images of {}'s strategies ({} ...)\n", result.extra_images.size(),
                   p.integrator_name, result.extra_images.front().name);
    const int ranks = group ? group->size() : 1;
    if (!args.stats.empty()) {
        RenderTimes times{setup_seconds, group ? group->communication_seconds : 0.0, ranks};
        write_stats(args.stats, args, *p.scene, result, p.integrator_name, p.options.seed, times);
    }
    if (!args.quiet)
        fmt::print(stderr, "{}x{}{}, {} spp in {:.2f} s: {:.3g} samples/s, {:.3g} rays/s on {}{} threads\n",
                   result.image.width(), result.image.height(),
                   result.image.width() != p.scene->width || result.image.height() != p.scene->height
                       ? fmt::format(" (of {}x{})", p.scene->width, p.scene->height)
                       : "",
                   result.spp, result.seconds, result.samples / result.seconds, result.rays / result.seconds,
                   ranks > 1 ? fmt::format("{} ranks of ", ranks) : "", result.threads);
    if (!args.quiet && result.adaptive)
        fmt::print(stderr, "adaptive: {}-{} samples per pixel in {} rounds, error level {:.3g} at the last\n",
                   result.adaptive->min_spp, result.adaptive->max_spp, result.adaptive->rounds,
                   result.adaptive->level);
    if (server) {
        server->finish();
        if (args.serve_linger > 0) {
            if (!args.quiet)
                fmt::print(stderr, "preview: serving the final image for {} s\n", args.serve_linger);
            std::this_thread::sleep_for(std::chrono::duration<double>(args.serve_linger));
        }
        server->stop();
    }
}

} // namespace

void add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd =
        app.add_subcommand("render", "Render a pbrt-v4 scene (default: the built-in Cornell box)");
    cmd->add_option("scene", args->scene, "Scene file (.pbrt); omit for the built-in Cornell box");
    cmd->add_option("-o,--output", args->outputs,
                    "Output image(s): .exr, .pfm, .hdr (linear) or .png (tone mapped)");
    cmd->add_option("--spp", args->spp, "Samples per pixel (default: the scene's)")
        ->check(positive_integer());
    cmd->add_option("--time", args->time, "Render whole passes until this many seconds are spent")
        ->check(positive_number());
    cmd->add_flag(
        "--adaptive", args->adaptive,
        "Adaptive sampling: the samples (spp x pixels, or --time) spread over the pixels in rounds, "
        "each pixel taking samples in proportion to the spread of its own and its neighbours' "
        "samples (which minimises the image's mean squared error); path, volpath, bdpt, direct and the "
        "debug passes, in one process");
    cmd->add_option("--adaptive-threshold", args->adaptive_threshold,
                    "With adaptive sampling, also stop pixels whose error level e = s / (n m) is below this "
                    "(s: the spread of the samples around the pixel, n: its samples, m: the image's mean), "
                    "ending the render early once all are; implies --adaptive (default 0: the budget "
                    "decides)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--adaptive-min-spp", args->adaptive_min_spp,
                    "With adaptive sampling, the samples every pixel takes first: a power of two, at least 2 "
                    "(default 16); implies --adaptive")
        ->check(positive_integer())
        ->check(CLI::Validator(
            [](const std::string& v) {
                const int n = std::atoi(v.c_str());
                return n >= 2 && (n & (n - 1)) == 0 ? std::string()
                                                    : "must be a power of two, at least 2, not \"" + v + "\"";
            },
            "POWER OF TWO"));
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(positive_integer());
    cmd->add_option("--seed", args->seed,
                    "Seed of the sample sequences (default: the scene's Sampler \"seed\", else its Option "
                    "\"seed\", else 0)");
    cmd->add_option("--integrator", args->integrator,
                    "path, volpath, bdpt, direct, albedo, normal, lightpath, sppm or vcm (default: the "
                    "scene's). vcm (vertex connection and merging) takes from the scene's Integrator "
                    "directive maxdepth, photonsperiteration (-1: pixels), radius (world units; default the "
                    "scene's bounding radius over the image's larger side), alpha (0.75), mode (vcm, vc or "
                    "vm) and misheuristic (balance or power)");
    cmd->add_option("--max-depth", args->max_depth,
                    "Maximum number of scattering events (default: the scene's)")
        ->check(CLI::Range(-1, 100000));
    cmd->add_option(
        "--sampler", args->sampler,
        "zsobol, sobol, paddedsobol, halton, pmj02bn, stratified or independent (default: the scene's)");
    cmd->add_option("--light-sampler", args->light_sampler,
                    "Next-event estimation's light choice: bvh (pbrt-v4's default: by distance and "
                    "orientation), power, uniform or exhaustive (default: the scene's \"lightsampler\")")
        ->check(CLI::IsMember({"bvh", "power", "uniform", "exhaustive"}));
    cmd->add_option("--resolution", args->resolution, "Film resolution WIDTHxHEIGHT (default: the scene's)");
    cmd->add_option("--stats", args->stats, "Write render statistics as JSON to this file");
    cmd->add_option("--tonemap", args->tonemap, "Tone map for PNG output: clamp, reinhard or aces");
    cmd->add_option("--exposure", args->exposure, "Exposure in stops for PNG output");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress or warnings");
    cmd->add_flag("--strict", args->strict, "Unsupported scene features are errors, not warnings");
    cmd->add_flag("--spectral", args->spectral,
                  "Render with four sampled wavelengths per camera sample (hero wavelength sampling) instead "
                  "of RGB");
    cmd->add_option(
        "--share", args->share,
        "Render only share RANK/RANKS of the samples, as that rank of an mpirun job would (to time "
        "a large job's ranks one by one; the image is that share's alone)");
    cmd->add_option("--serve", args->serve,
                    "Serve a live preview page at HOST:PORT or PORT (on 127.0.0.1; port 0 picks a free one) "
                    "while rendering");
    cmd->add_option("--serve-linger", args->serve_linger,
                    "Keep serving the preview this many seconds after the render is done")
        ->check(positive_number());
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli
