// `illum envmap`: tools for environment maps — layout conversion, spherical-harmonic irradiance, the
// brute-force irradiance map, and GGX prefiltering for real-time use (docs/emitters.md).
#include <filesystem>
#include <memory>

#include <fmt/core.h>

#include "commands.h"
#include "illum/analysis/envmap_plot.h"
#include "illum/envmap/irradiance.h"
#include "illum/envmap/prefilter.h"
#include "illum/envmap/resample.h"
#include "illum/envmap/spherical_harmonics.h"
#include "illum/image/drawing_io.h"
#include "illum/image/file_bytes.h"
#include "illum/image/image_io.h"
#include "illum/util/error.h"
#include "illum/util/progress.h"

namespace illum::cli {

namespace {

struct EnvArgs {
    std::string input, output, from, to, json, irradiance;
    int size = 0, levels = 6, samples = 256, lut_size = 128;
    bool quiet = false;
    float exposure = 0, scale = 1;
    bool fixed_exposure = false;
};

const char* kLayouts = "latlong, octahedral, mirrorball, angular or cubemap";

std::optional<EnvLayout> parse_layout(const std::string& s, const char* option) {
    if (s.empty()) return std::nullopt;
    auto l = env_layout_from_string(s);
    if (!l) throw Error(fmt::format("{}: unknown layout \"{}\" (expected {})", option, s, kLayouts));
    return l;
}

EnvironmentMap load(const EnvArgs& a) {
    return EnvironmentMap::load(a.input, parse_layout(a.from, "--from"));
}

void check_output(const std::string& path) {
    if (!is_supported_output_extension(path) || image_extension(path) == ".png")
        throw Error(fmt::format("\"{}\": the output must be .exr, .pfm or .hdr (radiance)", path));
}

void warn_sanitized(const EnvironmentMap& m, const std::string& path) {
    if (m.non_finite_count() > 0)
        fmt::print(stderr, "warning: \"{}\": {} non-finite values were set to 0\n", path,
                   m.non_finite_count());
    if (m.mean_radiance().is_black())
        fmt::print(stderr, "warning: \"{}\": the map is black (no energy)\n", path);
}

void run_convert(const EnvArgs& a) {
    EnvLayout to = *parse_layout(a.to, "--to");
    check_output(a.output);
    EnvironmentMap in = load(a);
    warn_sanitized(in, a.input);
    int h = a.size > 0 ? a.size : default_resample_height(in, to);
    Progress p("convert", std::uint64_t(h), "rows", a.quiet);
    EnvironmentMap out = resample(in, to, h, &p);
    p.finish();
    write_image(out.image(), a.output);
    Color3 mi = in.mean_radiance(), mo = out.mean_radiance();
    fmt::print("{} {}x{} -> {} {}x{}; mean radiance {:.6g} {:.6g} {:.6g} -> {:.6g} {:.6g} {:.6g}\n",
               to_string(in.layout()), in.width(), in.height(), to_string(to), out.width(), out.height(),
               mi[0], mi[1], mi[2], mo[0], mo[1], mo[2]);
}

void run_sh(const EnvArgs& a) {
    if (!a.irradiance.empty()) check_output(a.irradiance);
    EnvironmentMap in = load(a);
    warn_sanitized(in, a.input);
    SH9 sh = project_sh(in);
    fmt::print("{:<6}{:>14}{:>14}{:>14}\n", "", "R", "G", "B");
    for (int i = 0; i < 9; ++i)
        fmt::print("{:<6}{:14.6g}{:14.6g}{:14.6g}\n", kSHNames[i], sh.c[i][0], sh.c[i][1], sh.c[i][2]);
    if (!a.json.empty()) write_file_atomically(a.json, sh_to_json(sh));
    if (!a.irradiance.empty()) {
        EnvLayout to = a.to.empty() ? EnvLayout::LatLong : *parse_layout(a.to, "--to");
        int h = a.size > 0 ? a.size : 64;
        write_image(sh_irradiance_map(sh, to, h).image(), a.irradiance);
    }
}

void run_irradiance(const EnvArgs& a) {
    check_output(a.output);
    EnvironmentMap in = load(a);
    warn_sanitized(in, a.input);
    EnvLayout to = a.to.empty() ? EnvLayout::LatLong : *parse_layout(a.to, "--to");
    int h = a.size > 0 ? a.size : 64;
    Progress p("irradiance", std::uint64_t(h), "rows", a.quiet);
    EnvironmentMap e = brute_force_irradiance(in, to, h, 64, &p);
    p.finish();
    write_image(e.image(), a.output);
}

void run_prefilter(const EnvArgs& a) {
    EnvironmentMap in = load(a);
    warn_sanitized(in, a.input);
    std::error_code ec;
    std::filesystem::create_directories(a.output, ec);
    if (ec || !std::filesystem::is_directory(a.output))
        throw Error(fmt::format("cannot create the directory \"{}\"", a.output));
    PrefilterOptions opt;
    opt.height = a.size > 0 ? a.size : 128;
    opt.levels = a.levels;
    opt.samples = a.samples;
    Progress p("prefilter", std::uint64_t(prefilter_rows(opt)), "rows", a.quiet);
    auto chain = prefilter_ggx(in, opt, &p);
    p.finish();
    for (std::size_t i = 0; i < chain.size(); ++i) {
        float r = chain.size() > 1 ? float(i) / float(chain.size() - 1) : 0.0f;
        std::string path =
            (std::filesystem::path(a.output) / fmt::format("specular_{}_r{:.2f}.exr", i, r)).string();
        write_image(chain[i].image(), path);
        fmt::print("{}  {}x{}  roughness {:.2f}\n", path, chain[i].width(), chain[i].height(), r);
    }
    Progress pl("BRDF table", 1, "tables", a.quiet);
    Image lut = brdf_lut(a.lut_size, 1024);
    pl.add(1);
    pl.finish();
    std::string path = (std::filesystem::path(a.output) / "brdf_lut.exr").string();
    write_image(lut, path);
    fmt::print("{}  {}x{}  (x = N.V, y = roughness; R = scale, G = bias)\n", path, lut.width(), lut.height());
}

void run_show(const EnvArgs& a) {
    if (!is_drawing_extension(a.output))
        throw Error(fmt::format("-o \"{}\": the figure is written as .svg or .png", a.output));
    EnvironmentMap in = load(a);
    warn_sanitized(in, a.input);
    EnvmapFigureOptions opt;
    if (a.size > 0) opt.panel_height = a.size;
    opt.auto_exposure = !a.fixed_exposure;
    opt.exposure_stops = a.exposure;
    EnvmapFigure fig = envmap_figure(in, std::filesystem::path(a.input).filename().string(), opt);
    write_drawing(fig.drawing, a.output, a.scale);
    fmt::print("SH irradiance against brute force: mean |E_SH - E| / mean E = {:.2f}%; wrote {}\n",
               100 * fig.sh_mean_difference, a.output);
}

} // namespace

void add_envmap_command(CLI::App& app) {
    CLI::App* cmd =
        app.add_subcommand("envmap", "Environment-map tools: convert, sh, irradiance, prefilter, show");
    cmd->require_subcommand(1);
    auto common = [](CLI::App* c, EnvArgs& a) {
        c->add_option("--from", a.from,
                      fmt::format("Input layout: {} (default: by aspect ratio, 2:1 latlong, "
                                  "1:1 octahedral, 6:1 cubemap)",
                                  kLayouts));
        c->add_flag("-q,--quiet", a.quiet, "No progress bar");
    };
    {
        auto a = std::make_shared<EnvArgs>();
        CLI::App* c = cmd->add_subcommand("convert", "Resample an environment map into another layout");
        c->add_option("input", a->input, "Input map (.exr, .pfm, .hdr)")->required();
        c->add_option("output", a->output, "Output map (.exr, .pfm, .hdr)")->required();
        c->add_option("--to", a->to, fmt::format("Output layout: {}", kLayouts))->required();
        c->add_option("--size", a->size, "Output height in texels (default: about the input's texel count)")
            ->check(positive_integer());
        common(c, *a);
        c->callback([a] { run_convert(*a); });
    }
    {
        auto a = std::make_shared<EnvArgs>();
        CLI::App* c =
            cmd->add_subcommand("sh", "The nine spherical-harmonic radiance coefficients (Ramamoorthi & "
                                      "Hanrahan 2001)");
        c->add_option("input", a->input, "Input map")->required();
        c->add_option("--json", a->json, "Write {\"L00\": [r, g, b], ...} to this file");
        c->add_option("--irradiance", a->irradiance, "Render the SH irradiance map to this file");
        c->add_option("--to", a->to, "Layout of the irradiance map (default latlong)");
        c->add_option("--size", a->size, "Height of the irradiance map (default 64)")
            ->check(positive_integer());
        common(c, *a);
        c->callback([a] { run_sh(*a); });
    }
    {
        auto a = std::make_shared<EnvArgs>();
        CLI::App* c =
            cmd->add_subcommand("irradiance", "The exact irradiance map by brute-force convolution");
        c->add_option("input", a->input, "Input map")->required();
        c->add_option("output", a->output, "Output irradiance map (.exr, .pfm, .hdr)")->required();
        c->add_option("--to", a->to, "Output layout (default latlong)");
        c->add_option("--size", a->size, "Output height (default 64)")->check(positive_integer());
        common(c, *a);
        c->callback([a] { run_irradiance(*a); });
    }
    {
        auto a = std::make_shared<EnvArgs>();
        CLI::App* c =
            cmd->add_subcommand("prefilter", "GGX-prefiltered mip chain and BRDF table (split sum, Karis "
                                             "2013)");
        c->add_option("input", a->input, "Input map")->required();
        c->add_option("outdir", a->output, "Output directory")->required();
        c->add_option("--size", a->size, "Height of level 0 (default 128)")->check(positive_integer());
        c->add_option("--levels", a->levels, "Roughness levels (default 6)")->check(positive_integer());
        c->add_option("--samples", a->samples, "GGX samples per texel (default 256)")
            ->check(positive_integer());
        c->add_option("--lut-size", a->lut_size, "BRDF table size (default 128)")->check(positive_integer());
        common(c, *a);
        c->callback([a] { run_prefilter(*a); });
    }
    {
        auto a = std::make_shared<EnvArgs>();
        CLI::App* c = cmd->add_subcommand(
            "show", "Draw the map beside its SH irradiance and brute-force irradiance (SVG or PNG)");
        c->add_option("input", a->input, "Input map")->required();
        c->add_option("-o,--output", a->output, "The figure: .svg or .png")->required();
        c->add_option("--size", a->size, "Height of each latlong panel (default 180)")
            ->check(positive_integer());
        c->add_option("--exposure", a->exposure, "Exposure in stops, added to the automatic one");
        c->add_flag("--fixed-exposure", a->fixed_exposure, "No automatic exposure: only --exposure");
        c->add_option("--scale", a->scale, "PNG pixels per SVG unit")->check(CLI::Range(0.25, 8.0));
        common(c, *a);
        c->callback([a] { run_show(*a); });
    }
}

} // namespace illum::cli
