// `illum brdf fit`: an analytic model fitted to a measured MERL table or to another model's values
// (analysis/brdf_fit.h), printing its parameters and the fit error; `illum brdf tabulate`: a model
// written as a MERL table (to fit, or to render as the "merl" material).
#include <memory>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "brdf_args.h"
#include "commands.h"
#include "illum/analysis/brdf_fit.h"
#include "illum/bsdf/registry.h"

namespace illum::cli {

namespace {

struct FitOptions {
    std::string table, from, models = "ggx", output;
    std::vector<std::string> params;
    FitSampling sampling;
    int iterations = 200;
    bool json = false;
};

std::vector<FitFamily> families(const std::string& list) {
    std::vector<FitFamily> out;
    if (list == "all") return {FitFamily::GGX, FitFamily::Beckmann, FitFamily::Ward, FitFamily::CookTorrance};
    std::size_t start = 0;
    while (true) {
        std::size_t comma = list.find(',', start);
        std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        auto f = fit_family_from_string(name);
        if (!f)
            throw Error("--model: unknown model \"" + name +
                        "\" (fit one of ggx, beckmann, ward, cook-torrance, a comma-separated list, or all)");
        out.push_back(*f);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::string rgb_text(const Rgb64& c) { return fmt::format("{:.4f} {:.4f} {:.4f}", c[0], c[1], c[2]); }

void run_fit(const FitOptions& o) {
    if (o.table.empty() == o.from.empty())
        throw Error(
            "give one source to fit: a MERL table (illum brdf fit TABLE --model ...) or --from MODEL");
    std::vector<FitFamily> fams = families(o.models);
    BrdfSamples samples;
    std::string source;
    if (!o.table.empty()) {
        samples = samples_from_merl(MerlTable::read(o.table), o.sampling);
        source = "\"" + o.table + "\"";
    } else {
        const ModelSpec& spec = find_bxdf_model(o.from);
        ParamValues values = resolve_params(spec, parse_kv(o.params));
        samples = samples_from_bxdf(*spec.make(values), o.sampling);
        source = spec.name + (values.args.empty() ? "" : " " + values.describe());
    }
    if (samples.size() == 0)
        throw Error("no direction pairs to fit (every bin is missing or beyond --max-theta)");
    nlohmann::json out;
    out["source"] = source;
    out["pairs"] = samples.size();
    out["metric"] = "sum over pairs and RGB of [ln(1 + f cos theta_i) - ln(1 + fit cos theta_i)]^2";
    out["fits"] = nlohmann::json::array();
    if (!o.json) {
        fmt::print("# fit to {}: {} direction pairs at MERL bin centres (every θh, every {} θd, every {} φd; "
                   "θi, θo <= "
                   "{:g}°)\n",
                   source, samples.size(), o.sampling.theta_d_stride, o.sampling.phi_d_stride,
                   o.sampling.max_theta_deg);
        fmt::print(
            "# f = ρd/π + ρs lobe; least squares on ln(1 + f cos θi) (cosine weighting of Ngan et al. 2005), "
            "Levenberg-Marquardt\n");
        fmt::print("{:<14} {:>8} {:>7}  {:<22}  {:<22}  {:>10} {:>10} {:>5}\n", "model", "alpha/m", "F0",
                   "rho_d (R G B)", "rho_s (R G B)", "log-RMS", "rel. RMS", "iter");
    }
    for (FitFamily f : fams) {
        FitResult r = fit_brdf(samples, f, o.iterations);
        const FitParameters& p = r.params;
        if (!o.json)
            fmt::print("{:<14} {:>8.4f} {:>7}  {:<22}  {:<22}  {:>10.3e} {:>10.3e} {:>5}{}\n", to_string(f),
                       p.alpha, f == FitFamily::CookTorrance ? fmt::format("{:.4f}", p.f0) : "-",
                       rgb_text(p.rho_d), rgb_text(p.rho_s), r.error.log_rms, r.error.relative_rms,
                       r.iterations, r.converged ? "" : "  (" + r.stop + ")");
        nlohmann::json j = {{"model", to_string(f)},
                            {"alpha", p.alpha},
                            {"rho_d", {p.rho_d[0], p.rho_d[1], p.rho_d[2]}},
                            {"rho_s", {p.rho_s[0], p.rho_s[1], p.rho_s[2]}},
                            {"log_rms", r.error.log_rms},
                            {"relative_rms", r.error.relative_rms},
                            {"iterations", r.iterations},
                            {"converged", r.converged},
                            {"stop", r.stop}};
        if (f == FitFamily::CookTorrance) j["f0"] = p.f0;
        out["fits"].push_back(j);
    }
    if (o.json) fmt::print("{}\n", out.dump(1));
}

} // namespace

void add_brdf_fit_command(CLI::App& brdf) {
    auto o = std::make_shared<FitOptions>();
    CLI::App* fit = brdf.add_subcommand(
        "fit", "fit ggx, beckmann, ward or cook-torrance to a MERL table or to another model's values");
    fit->add_option("table", o->table, "MERL .binary table to fit");
    fit->add_option("--model,-m", o->models,
                    "ggx, beckmann, ward, cook-torrance, a comma-separated list, or all");
    fit->add_option("--from", o->from, "fit to this registry model's values instead of a table");
    fit->add_option("--param,-p", o->params, "parameter name=value of the --from model (repeatable)");
    fit->add_option("--theta-d-stride", o->sampling.theta_d_stride, "use every N-th θd bin")
        ->check(CLI::Range(1, 90));
    fit->add_option("--phi-d-stride", o->sampling.phi_d_stride, "use every N-th φd bin")
        ->check(CLI::Range(1, 180));
    fit->add_option("--max-theta", o->sampling.max_theta_deg,
                    "leave out pairs beyond this angle from the normal")
        ->check(CLI::Range(1.0, 90.0));
    fit->add_option("--iterations", o->iterations, "Levenberg-Marquardt iteration limit")
        ->check(CLI::Range(1, 100000));
    fit->add_flag("--json", o->json, "print the fits as JSON");
    fit->callback([o] { run_fit(*o); });

    auto t = std::make_shared<FitOptions>();
    CLI::App* tab = brdf.add_subcommand("tabulate", "write a model's reflection as a MERL .binary table");
    tab->add_option("model", t->from, "model name")->required();
    tab->add_option("--param,-p", t->params, "parameter name=value (repeatable)");
    tab->add_option("-o,--output", t->output, "the MERL table to write")->required();
    tab->callback([t] {
        const ModelSpec& spec = find_bxdf_model(t->from);
        MerlTable::from_bxdf(*spec.make(resolve_params(spec, parse_kv(t->params)))).write(t->output);
        fmt::print("wrote {} (90 x 90 x 180 bins, MERL format)\n", t->output);
    });
}

} // namespace illum::cli
