// `illum diff IMAGE REFERENCE`: channel means of both, their relative differences, and the per-pixel
// error metrics (RMSE, relMSE, mean relative error) when the sizes agree; pixels with Inf/NaN are left
// out of all of them and counted.
#include <fmt/core.h>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "illum/image/image_io.h"
#include "illum/image/metrics.h"

namespace illum::cli {

namespace {

struct DiffArgs {
    std::string image, reference;
    bool json = false;
    double trim = kTrimFraction;
};

nlohmann::json to_json(const ErrorStats& s) {
    return {{"r", s.channel[0]}, {"g", s.channel[1]}, {"b", s.channel[2]}, {"all", s.overall}};
}

void run(const DiffArgs& args) {
    Image a = read_image(args.image), b = read_image(args.reference);
    // Pixels with an Inf or NaN are left out (and counted): one of them would turn every figure into Inf
    // or NaN and hide how the rest of the image compares.
    const FiniteComparison d = compare_finite(a, b, kRelativeEps, args.trim);
    if (args.json) {
        nlohmann::json j = {
            {"image", args.image},
            {"reference", args.reference},
            {"nonfinite_pixels", {{"image", d.nonfinite}, {"reference", d.reference_nonfinite}}},
            {"mean", to_json(d.mean)},
            {"reference_mean", to_json(d.reference_mean)},
            {"relative_mean_difference", to_json(d.relative_mean_difference)}};
        if (d.rmse) {
            j["compared_pixels"] = d.compared;
            j["rmse"] = to_json(*d.rmse);
            j["relmse"] = to_json(*d.rel_mse);
            j["mean_relative_error"] = to_json(*d.mean_relative_error);
            j["rmse_trimmed"] = to_json(*d.rmse_trimmed);
            j["trimmed_pixels"] = d.trimmed;
        }
        fmt::print("{}\n", j.dump(2));
        return;
    }
    // Explicit right alignment: fmt aligns inf and nan to the left otherwise (a mean difference is inf
    // when a reference mean is 0), which breaks the columns.
    auto row = [](const std::string& name, const ErrorStats& s, const char* fmt_spec) {
        fmt::print("{:<26}", name);
        for (double v : s.channel) fmt::print(fmt::runtime(fmt_spec), v);
        fmt::print(fmt::runtime(fmt_spec), s.overall);
        fmt::print("\n");
    };
    fmt::print("{:<26}{:>12}{:>12}{:>12}{:>12}\n", "", "R", "G", "B", "all");
    row(fmt::format("mean {}x{}", a.width(), a.height()), d.mean, "{:>12.6g}");
    row(fmt::format("reference mean {}x{}", b.width(), b.height()), d.reference_mean, "{:>12.6g}");
    ErrorStats pct = d.relative_mean_difference;
    for (double& v : pct.channel) v *= 100;
    pct.overall *= 100;
    row("mean difference (%)", pct, "{:>12.3f}");
    if (d.rmse) {
        row("RMSE", *d.rmse, "{:>12.5g}");
        row("relMSE", *d.rel_mse, "{:>12.5g}");
        row("mean relative error", *d.mean_relative_error, "{:>12.5g}");
        row(fmt::format("RMSE, {} px trimmed", d.trimmed), *d.rmse_trimmed, "{:>12.5g}");
    } else {
        fmt::print("(sizes differ: per-pixel metrics skipped)\n");
    }
    if (d.nonfinite || d.reference_nonfinite)
        fmt::print("excluded {} pixel{} with Inf/NaN in {}, {} in {}\n", d.nonfinite,
                   d.nonfinite == 1 ? "" : "s", args.image, d.reference_nonfinite, args.reference);
}

} // namespace

void add_diff_command(CLI::App& app) {
    auto args = std::make_shared<DiffArgs>();
    CLI::App* cmd = app.add_subcommand("diff", "Compare an image with a reference (means and error metrics)");
    cmd->add_option("image", args->image, "Image (.exr, .pfm, .hdr, .png)")->required();
    cmd->add_option("reference", args->reference, "Reference image")->required();
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    cmd->add_option("--trim", args->trim,
                    "Fraction of the pixels with the largest errors (fireflies) that the trimmed RMSE leaves "
                    "out")
        ->check(CLI::Range(0.0, 0.5))
        ->capture_default_str();
    cmd->callback([args] { run(*args); });
}

} // namespace illum::cli
