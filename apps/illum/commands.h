// One function per subcommand file: each adds its subcommand (options and callback) to the CLI app.
// Callbacks report user errors by throwing illum::Error; main() prints them and exits 2.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <utility>

#include "illum/util/error.h"
#include <string>

namespace illum::cli {

// Option validators with messages a person can read.
inline CLI::Validator positive_integer() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            try {
                std::size_t used = 0;
                long long v = std::stoll(s, &used);
                if (used == s.size() && v > 0 && v <= 2147483647) return {};
            } catch (...) {
            }
            return "must be a positive whole number, not \"" + s + "\"";
        },
        "N>0");
}
// "WIDTHxHEIGHT" for --resolution; throws illum::Error naming the option's value otherwise.
inline std::pair<int, int> parse_resolution(const std::string& s) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w <= 0 ||
        h <= 0)
        throw Error("--resolution \"" + s + "\" is not WIDTHxHEIGHT");
    return {w, h};
}

inline CLI::Validator positive_number() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            try {
                std::size_t used = 0;
                double v = std::stod(s, &used);
                if (used == s.size() && v > 0 && std::isfinite(v)) return {};
            } catch (...) {
            }
            return "must be a positive number, not \"" + s + "\"";
        },
        "X>0");
}

void add_render_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_brdf_command(CLI::App& app);
void add_diff_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_envmap_command(CLI::App& app);
void add_photons_command(CLI::App& app);
void add_verify_command(CLI::App& app);
// Subcommands of `illum brdf` in files of their own.
void add_brdf_plot_commands(CLI::App& brdf);
void add_brdf_fit_command(CLI::App& brdf);

} // namespace illum::cli
