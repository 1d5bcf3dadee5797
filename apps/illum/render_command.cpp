// `illum render [SCENE] [-o OUT.{exr,pfm,hdr,png}]...`: renders a pbrt-v4 scene, or the built-in Cornell
// box when no scene is named.
#include <cstdio>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "commands.h"
#include "illum/image/image_io.h"
#include "illum/image/tonemap.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/util/error.h"
#include "scene_loading.h"

namespace illum::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::vector<std::string> outputs;
    int spp = 0; // 0: the scene's
    double time = 0;
    int threads = 0;
    std::uint64_t seed = 0;
    std::string integrator; // "": the scene's
    int max_depth = -2;     // -2: the scene's
    std::string sampler;
    std::string resolution; // WxH
    std::string stats;
    std::string tonemap = "clamp";
    float exposure = 0;
    bool quiet = false;
    bool strict = false;
    bool spectral = false;
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

void write_stats(const std::string& path, const RenderArgs& args, const Scene& scene, const RenderResult& r,
                 const std::string& integrator) {
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
    j["seed"] = args.seed;
    j["nonfinite_samples"] = r.nonfinite_samples;
    j["mode"] = args.spectral ? "spectral" : "rgb";
    j["color_space"] = std::string(scene.color_space->name());
    std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp);
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
        out << j.dump(2) << "\n";
        if (!out) throw Error(fmt::format("cannot write \"{}\"", path));
    }
    std::filesystem::rename(tmp, path);
}

void run(const RenderArgs& args) {
    auto tonemap = tonemap_from_string(args.tonemap);
    if (!tonemap)
        throw Error(fmt::format("unknown tone map \"{}\" (use clamp, reinhard or aces)", args.tonemap));
    for (const auto& o : args.outputs) check_output(o);
    if (!args.stats.empty()) check_output_folder_only(args.stats);

    SceneDesc desc = load_scene_desc(args.scene, args.strict);
    if (!args.resolution.empty()) {
        auto [w, h] = parse_resolution(args.resolution);
        desc.set_film_resolution(w, h);
    }
    BuildOptions build_options;
    build_options.strict = args.strict;
    std::unique_ptr<Scene> scene = build_scene(desc, build_options);
    if (!args.quiet) print_warnings(scene->warnings);

    std::vector<std::string> outputs = args.outputs;
    if (outputs.empty()) {
        std::string name = scene->request.output.empty() ? "illum.exr" : scene->request.output;
        if (!is_supported_output_extension(name))
            name = std::filesystem::path(name).replace_extension(".exr").string();
        // The film's filename is relative to where illum runs, as in pbrt.
        check_output(name);
        outputs.push_back(name);
    }

    std::string integrator_name = args.integrator.empty() ? scene->request.integrator : args.integrator;
    int max_depth = args.max_depth == -2 ? scene->request.max_depth : args.max_depth;
    auto integrator = make_integrator(integrator_name, *scene, max_depth);

    RenderOptions options;
    options.spp = args.spp > 0 ? args.spp : scene->request.spp;
    options.time_budget = args.time;
    options.threads = args.threads;
    options.seed = args.seed;
    options.sampler = args.sampler.empty() ? scene->request.sampler : args.sampler;
    options.quiet = args.quiet;
    options.spectral = args.spectral;
    RenderResult result = render(*scene, *integrator, options);
    if (result.nonfinite_samples > 0 && !args.quiet)
        fmt::print(stderr, "warning: {} samples were NaN, infinite or negative and were dropped\n",
                   result.nonfinite_samples);

    WriteOptions wo;
    wo.exposure_stops = args.exposure;
    wo.tonemap = *tonemap;
    for (const auto& o : outputs) {
        write_image(result.image, o, wo);
        if (!args.quiet) fmt::print(stderr, "wrote {}\n", o);
    }
    if (!args.stats.empty()) write_stats(args.stats, args, *scene, result, integrator_name);
    if (!args.quiet)
        fmt::print(stderr, "{}x{}, {} spp in {:.2f} s: {:.3g} samples/s, {:.3g} rays/s on {} threads\n",
                   scene->width, scene->height, result.spp, result.seconds, result.samples / result.seconds,
                   result.rays / result.seconds, result.threads);
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
    cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")
        ->check(positive_integer());
    cmd->add_option("--seed", args->seed, "Seed of the sample sequences");
    cmd->add_option("--integrator", args->integrator,
                    "path, volpath, bdpt, direct, albedo, normal, lightpath or sppm (default: the scene's)");
    cmd->add_option("--max-depth", args->max_depth,
                    "Maximum number of scattering events (default: the scene's)")
        ->check(CLI::Range(-1, 100000));
    cmd->add_option("--sampler", args->sampler, "sobol or independent (default: the scene's)");
    cmd->add_option("--resolution", args->resolution, "Film resolution WIDTHxHEIGHT (default: the scene's)");
    cmd->add_option("--stats", args->stats, "Write render statistics as JSON to this file");
    cmd->add_option("--tonemap", args->tonemap, "Tone map for PNG output: clamp, reinhard or aces");
    cmd->add_option("--exposure", args->exposure, "Exposure in stops for PNG output");
    cmd->add_flag("-q,--quiet", args->quiet, "No progress or warnings");
    cmd->add_flag("--strict", args->strict, "Unsupported scene features are errors, not warnings");
    cmd->add_flag("--spectral", args->spectral,
                  "Render with four sampled wavelengths per camera sample (hero wavelength sampling) instead "
                  "of RGB");
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli
