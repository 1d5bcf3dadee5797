// `illum brdf plot` and `illum brdf compare`: the lobe of one model, or two overlaid, in the plane of
// incidence, over the sphere, and the directional albedo against θi (analysis/brdf_plot.h), as SVG or PNG.
#include <memory>

#include <fmt/core.h>

#include "brdf_args.h"
#include "commands.h"
#include "illum/analysis/brdf_plot.h"
#include "illum/bsdf/registry.h"
#include "illum/image/drawing_io.h"
#include "illum/image/file_bytes.h"

namespace illum::cli {

namespace {

struct PlotOptions {
    std::string model_a, model_b;
    std::vector<std::string> params_a, params_b;
    std::string wi = "30,0", output, data;
    int grid = 180;
    float scale = 1;
};

BrdfPlotData model_data(const std::string& model, const std::vector<std::string>& params,
                        const PlotOptions& o) {
    const ModelSpec& spec = find_bxdf_model(model);
    ParamValues values = resolve_params(spec, parse_kv(params));
    auto bxdf = spec.make(values);
    auto [theta, phi] = parse_theta_phi(o.wi, "--wi");
    if (theta == 90)
        throw Error("--wi: light at θ = 90° (grazing) delivers no power; use θ in [0, 90) or (90, 180]");
    LobeOptions lo;
    lo.n_theta = o.grid;

    std::string label = spec.name + (values.args.empty() ? "" : " " + values.describe());
    return brdf_plot_data(*bxdf, label, theta, phi, default_albedo_thetas(), lo);
}

void check_output(const PlotOptions& o) {
    if (!is_drawing_extension(o.output))
        throw Error("-o \"" + o.output + "\": a plot is written as .svg or .png");
}

void write(const std::vector<BrdfPlotData>& models, const PlotOptions& o) {
    write_drawing(brdf_figure(models), o.output, o.scale);
    if (!o.data.empty()) write_file_atomically(o.data, brdf_plot_json(models));
    for (const auto& m : models) {
        Rgb64 a = m.lobe.albedo();
        fmt::print("{}: albedo at θi = {:g}° (integral of the plotted lobe) = {:.4f} {:.4f} {:.4f}\n",
                   m.label, m.theta_i_deg, a[0], a[1], a[2]);
    }
    fmt::print("wrote {}{}\n", o.output, o.data.empty() ? "" : " and " + o.data);
}

void common(CLI::App* c, PlotOptions& o) {
    c->add_option("--wi", o.wi,
                  "direction towards the light, θ,φ in degrees (θ from the normal; default 30,0)");
    c->add_option("-o,--output", o.output, "the figure: .svg (vector) or .png (rasterised)")->required();
    c->add_option("--data", o.data, "also write the plotted data (RGB) as JSON to this file");
    c->add_option("--grid", o.grid, "lobe grid cells in θ per hemisphere (φ has twice as many; default 180)")
        ->check(CLI::Range(8, 1024));
    c->add_option("--scale", o.scale, "PNG pixels per SVG unit (default 1)")->check(CLI::Range(0.25, 8.0));
}

} // namespace

void add_brdf_plot_commands(CLI::App& brdf) {
    auto o = std::make_shared<PlotOptions>();
    CLI::App* plot = brdf.add_subcommand(
        "plot", "draw a model's lobe f·|cos| (plane of incidence, 3D mesh) and its albedo against θi");
    plot->add_option("model", o->model_a, "model name (see `illum brdf list`)")->required();
    plot->add_option(
        "--param,-p", o->params_a,
        "parameter name=value (repeatable; rgb as r,g,b). The layered models' f() is a random-walk "
        "estimate: -p samples=16 smooths their lobe");
    common(plot, *o);
    plot->callback([o] {
        check_output(*o);
        write({model_data(o->model_a, o->params_a, *o)}, *o);
    });

    auto c = std::make_shared<PlotOptions>();
    CLI::App* compare = brdf.add_subcommand("compare", "overlay the lobes and albedos of two models");
    compare->add_option("model_a", c->model_a, "first model")->required();
    compare->add_option("model_b", c->model_b, "second model")->required();
    compare->add_option("--param-a,-a", c->params_a, "parameter name=value of the first model (repeatable)");
    compare->add_option("--param-b,-b", c->params_b, "parameter name=value of the second model (repeatable)");
    common(compare, *c);
    compare->callback([c] {
        check_output(*c);
        write({model_data(c->model_a, c->params_a, *c), model_data(c->model_b, c->params_b, *c)}, *c);
    });
}

} // namespace illum::cli
