// Loading a scene for the CLI: illum::load_scene_desc (illum/scene/load.h: a pbrt-v4 file, or the built-in
// Cornell box when no file is named), which the subcommands find from illum::cli, and the CLI's warnings.
#pragma once

#include <string>
#include <vector>

#include "illum/scene/load.h"

namespace illum::cli {

// Prints each warning as `warning: ...` on stderr.
void print_warnings(const std::vector<std::string>& warnings);

} // namespace illum::cli
