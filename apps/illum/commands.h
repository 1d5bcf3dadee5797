// One function per subcommand file: each adds its subcommand (options and callback) to the CLI app.
// Callbacks report user errors by throwing illum::Error; main() prints them and exits 2.
#pragma once

#include <CLI/CLI.hpp>

namespace illum::cli {

void add_render_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_brdf_command(CLI::App& app);
void add_diff_command(CLI::App& app);

} // namespace illum::cli
