// `illum brdf`: list the reflection models, evaluate one, tabulate its directional albedo, audit it, and
// compare exact Fresnel with Schlick's approximation.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "brdf_args.h"
#include "commands.h"
#include "illum/analysis/audit.h"
#include "illum/analysis/gallery.h"
#include "illum/bsdf/albedo.h"
#include "illum/bsdf/conductor.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/registry.h"
#include "illum/image/image_io.h"
#include "illum/radiometry/conductor_rgb.h"
#include "illum/render/renderer.h"
#include "illum/util/error.h"

namespace illum::cli {

namespace {

void list_models() {
    for (const auto& m : bxdf_models()) {
        fmt::print("{}{}\n  {}\n", m.name, m.non_physical ? "  [non-physical]" : "", m.description);
        for (const auto& p : m.params) {
            std::string range;
            if (p.kind == ParamKind::Choice) {
                for (const auto& c : p.choices) range += (range.empty() ? "" : "|") + c;
            } else if (p.kind != ParamKind::Path) {
                range = fmt::format("[{:g}, {:g}]", p.min, p.max);
            }
            fmt::print("    {:<14} {:<8} default {:<28} {:<18} {}\n", p.name, to_string(p.kind),
                       p.default_value.empty() ? "-" : p.default_value, range, p.description);
        }
    }
}

struct BrdfOptions {
    std::string model;
    std::vector<std::string> params;
    std::string wi = "30,0", wo = "30,180", mode = "radiance", thetas = "0,30,60,80";
    bool json = false;
    int samples = 200000, quad = 256;
    std::uint64_t seed = 1;
    std::string audit_target = "all";
    bool verbose = false;
    double eta = 1.5;
    std::string metal = "gold";
};

} // namespace

void add_brdf_command(CLI::App& app) {
    auto opt = std::make_shared<BrdfOptions>();
    CLI::App* brdf = app.add_subcommand(
        "brdf",
        "reflection models: list, eval, albedo, audit, fresnel, gallery, plot, compare, fit, tabulate");
    brdf->require_subcommand(1);

    brdf->add_subcommand("list", "name every model with its parameters, defaults and ranges")->callback([] {
        list_models();
    });

    CLI::App* eval =
        brdf->add_subcommand("eval", "print f (RGB, 1/sr) and pdf (1/sr) for one pair of directions");
    eval->add_option("model", opt->model, "model name (see `illum brdf list`)")->required();
    eval->add_option("--param,-p", opt->params, "parameter name=value (repeatable; rgb as r,g,b)");
    eval->add_option("--wi", opt->wi, "incident direction θ,φ in degrees (towards the light)");
    eval->add_option("--wo", opt->wo, "outgoing direction θ,φ in degrees (towards the viewer)");
    eval->add_option("--mode", opt->mode, "transport mode: radiance or importance");
    eval->add_flag("--json", opt->json, "print {\"f\": [r, g, b], \"pdf\": p}");
    eval->callback([opt] {
        auto bxdf = make_bxdf(opt->model, parse_kv(opt->params));
        Vector3f wi = parse_angles(opt->wi, "--wi"), wo = parse_angles(opt->wo, "--wo");
        if (opt->mode != "radiance" && opt->mode != "importance")
            throw Error("--mode must be radiance or importance, got '" + opt->mode + "'");
        auto mode = opt->mode == "radiance" ? TransportMode::Radiance : TransportMode::Importance;
        Color3 f = bxdf->f(wo, wi, mode).rgb();
        float pdf = bxdf->pdf(wo, wi, mode).value;
        if (opt->json)
            fmt::print("{{\"f\": [{:.9g}, {:.9g}, {:.9g}], \"pdf\": {:.9g}}}\n", f.r, f.g, f.b, pdf);
        else
            fmt::print("f   = {:.6g} {:.6g} {:.6g}  [1/sr]\npdf = {:.6g}  [1/sr]\n", f.r, f.g, f.b, pdf);
    });

    CLI::App* albedo =
        brdf->add_subcommand("albedo", "directional albedo ∫ f |cos θi| dωi by quadrature and MC");
    albedo->add_option("model", opt->model, "model name")->required();
    albedo->add_option("--param,-p", opt->params, "parameter name=value (repeatable)");
    albedo->add_option("--theta", opt->thetas, "comma-separated θo in degrees");
    albedo->add_option("--samples", opt->samples, "Monte Carlo samples per θo")
        ->check(CLI::Range(100, 100000000));
    albedo->add_option("--quad", opt->quad, "quadrature points in θ per hemisphere (φ uses twice as many)")
        ->check(CLI::Range(8, 4096));
    albedo->add_option("--seed", opt->seed, "random seed");
    albedo->callback([opt] {
        const ModelSpec& spec = find_bxdf_model(opt->model);
        ParamValues values = resolve_params(spec, parse_kv(opt->params));
        auto bxdf = spec.make(values);
        std::string ps;
        ps = values.describe();
        fmt::print("# {} {}\n", spec.name, ps);
        fmt::print(
            "# albedo = ∫ f(wo,wi) |cos θi| dωi (importance mode), RGB; MC: {} samples, ± 1 standard error\n",
            opt->samples);
        fmt::print("{:>6}  {:<30}  {}\n", "θo", "quadrature", "monte carlo");
        for (double t : parse_list(opt->thetas, "--theta")) {
            if (!(t >= 0 && t < 90)) throw Error(fmt::format("--theta values must be in [0, 90), got {}", t));
            auto e = directional_albedo(*bxdf, direction_deg(t, 0), spec.delta, opt->quad, opt->samples,
                                        opt->seed);
            std::string q = e.has_quadrature ? fmt::format("{:.4f} {:.4f} {:.4f}", e.quadrature[0],
                                                           e.quadrature[1], e.quadrature[2])
                                             : "- (delta)";
            fmt::print("{:>6g}  {:<30}  {:.4f} {:.4f} {:.4f}  ± {:.4f} {:.4f} {:.4f}\n", t, q, e.mc[0],
                       e.mc[1], e.mc[2], e.mc_stderr[0], e.mc_stderr[1], e.mc_stderr[2]);
        }
    });

    CLI::App* audit =
        brdf->add_subcommand("audit", "positivity, reciprocity, energy, sampling checks; exits 1 on failure");
    audit->add_option("model", opt->audit_target, "model name or 'all'");
    audit->add_option("--seed", opt->seed, "random seed");
    audit->add_flag("-v,--verbose", opt->verbose, "print every check's figures, not only failures");
    audit->callback([opt] {
        std::vector<const ModelSpec*> models;
        if (opt->audit_target == "all")
            for (const auto& m : bxdf_models()) models.push_back(&m);
        else
            models.push_back(&find_bxdf_model(opt->audit_target));
        AuditOptions ao;
        ao.seed = opt->seed;
        // Sidak over every chi-square test of the run.
        int tests = 0;
        for (const ModelSpec* m : models)
            for (const auto& c : m->audit_grid) {
                ParamValues v = resolve_params(*m, c.params);
                auto b = m->make(v);
                AuditTraits t;
                t.delta = m->delta;
                t.stochastic = m->stochastic;
                tests += count_chi2_tests(*b, t, ao);
            }
        ao.chi2_tests = std::max(1, tests);
        bool ok = true;
        int cases = 0, failed = 0;
        fmt::print("{:<20} {:<44} {}\n", "model", "parameters", "checks");
        for (const ModelSpec* m : models) {
            for (const auto& r : audit_model(*m, ao)) {
                ++cases;
                std::string line;
                for (const auto& c : r.checks) line += fmt::format("{}:{} ", c.name, to_string(c.status));
                fmt::print("{:<20} {:<44} {}\n", r.model, r.params, line);
                for (const auto& c : r.checks)
                    if (opt->verbose || c.status == CheckStatus::Fail || c.status == CheckStatus::Info)
                        fmt::print("    {} {}: {}\n", to_string(c.status), c.name, c.detail);
                if (!r.passed()) {
                    ok = false;
                    ++failed;
                }
            }
        }
        fmt::print("{} cases, {} failed; {} chi-square tests, family-wise significance 1% (Sidak)\n", cases,
                   failed, ao.chi2_tests);
        std::fflush(stdout);
        if (!ok) throw CLI::RuntimeError(1);
    });

    struct GalleryOptions {
        std::string output = "gallery.png";
        int spp = 256;
        std::string resolution = "1200x600";
        int threads = 0;
        bool quiet = false;
    };
    auto gal = std::make_shared<GalleryOptions>();
    CLI::App* gallery =
        brdf->add_subcommand("gallery", "render one sphere per model (default parameters) in a grid");
    gallery->add_option("-o,--output", gal->output, "output image (.png tone mapped; .exr/.pfm/.hdr linear)");
    gallery->add_option("--spp", gal->spp, "samples per pixel")->check(positive_integer());
    gallery->add_option("--resolution", gal->resolution, "WIDTHxHEIGHT");
    gallery->add_option("--threads", gal->threads, "worker threads (default: all)")
        ->check(positive_integer());
    gallery->add_flag("-q,--quiet", gal->quiet, "no progress");
    gallery->callback([gal] {
        auto [w, h] = parse_resolution(gal->resolution);
        if (!is_supported_output_extension(gal->output))
            throw Error("cannot write \"" + gal->output + "\": unknown image extension \"" +
                        image_extension(gal->output) + "\" (use .exr, .pfm, .hdr or .png)");
        auto scene = make_gallery_scene(w, h);
        auto integrator = make_integrator("path", *scene, scene->request.max_depth);
        RenderOptions ro;
        ro.spp = gal->spp;
        ro.threads = gal->threads;
        ro.quiet = gal->quiet;
        RenderResult r = render(*scene, *integrator, ro);
        WriteOptions wo;
        wo.tonemap = ToneMap::Aces;
        write_image(r.image, gal->output, wo);
        if (!gal->quiet) {
            fmt::print("models, left to right and top to bottom:\n");
            for (const auto& e : gallery_entries()) fmt::print("  {}\n", e.model);
            fmt::print("wrote {}\n", gal->output);
        }
    });

    CLI::App* fres = brdf->add_subcommand("fresnel", "exact Fresnel against Schlick's approximation over θ");
    fres->add_option("--eta", opt->eta, "dielectric index of refraction")->check(positive_number());
    fres->add_option(
        "--metal", opt->metal,
        "conductor: gold (the registry's RGB gold), a measured material of pbrt-v4's named spectra "
        "(Ag, Al, Au, Cu, CuZn, MgO, TiO2: its RGB index fitted to the spectra), or n,k");
    fres->callback([opt] {
        Color3 n = kGoldEta, k = kGoldK;
        std::string name = "gold (RGB)";
        if (const ConductorRgb* c = named_conductor_rgb(opt->metal)) {
            n = c->eta;
            k = c->k;
            Color3 f0 = reflectance_rgb(*measured_index(opt->metal), 1.0);
            name = fmt::format(
                "{} (η = {:.4f} {:.4f} {:.4f}, k = {:.4f} {:.4f} {:.4f}; spectral F0 = {:.4f} {:.4f} "
                "{:.4f})",
                opt->metal, n.r, n.g, n.b, k.r, k.g, k.b, f0.r, f0.g, f0.b);
        } else if (opt->metal != "gold") {
            auto v = opt->metal.find(',') == std::string::npos ? std::vector<double>{}
                                                               : parse_list(opt->metal, "--metal");
            if (v.size() != 2 || !(v[0] > 0) || !(v[1] >= 0))
                throw Error(
                    "--metal expects gold, Ag, Al, Au, Cu, CuZn, MgO, TiO2 or n,k with n > 0, k >= 0");
            n = Color3(float(v[0]));
            k = Color3(float(v[1]));
            name = opt->metal;
        }
        float eta = float(opt->eta);
        SampledSpectrum sn(n), sk(k);
        Color3 f0 = conductor_f0(sn, sk).rgb();
        fmt::print("# dielectric η = {:g}: F0 = {:.4f};  conductor {}: F0 = {:.4f} {:.4f} {:.4f}\n", eta,
                   dielectric_f0(eta), name, f0.r, f0.g, f0.b);
        fmt::print("{:>5} | {:>8} {:>8} {:>9} | {:>24} {:>24} {:>27}\n", "θ", "exact", "schlick", "diff",
                   "conductor exact (RGB)", "schlick (RGB)", "diff (RGB)");
        for (int t = 0; t <= 90; t += 5) {
            float c = std::cos(t * kPi / 180);
            float fe = fresnel_dielectric(c, eta), fs = fresnel_dielectric_schlick(c, eta);
            Color3 ce = fresnel_complex(c, sn, sk).rgb(), cs = fresnel_schlick(c, SampledSpectrum(f0)).rgb(),
                   d = cs - ce;
            fmt::print("{:>5} | {:>8.4f} {:>8.4f} {:>+9.4f} | {:>7.4f} {:>7.4f} {:>7.4f}  {:>7.4f} {:>7.4f} "
                       "{:>7.4f}  "
                       "{:>+8.4f} {:>+8.4f} {:>+8.4f}\n",
                       t, fe, fs, fs - fe, ce.r, ce.g, ce.b, cs.r, cs.g, cs.b, d.r, d.g, d.b);
        }
    });

    add_brdf_plot_commands(*brdf);
    add_brdf_fit_command(*brdf);
}

} // namespace illum::cli
