// One function per subcommand file: each adds its subcommand (options and callback) to the CLI app.
// Callbacks report user errors by throwing illum::Error; main() prints them and exits 2.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
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

} // namespace illum::cli
