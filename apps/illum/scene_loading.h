// Loading a scene for the CLI: a pbrt-v4 file, or the built-in Cornell box when no file is named.
#pragma once

#include <string>

#include "illum/scene/scene_desc.h"

namespace illum::cli {

// `strict` (--strict): the parser's warnings are errors, as the builder's are with BuildOptions::strict.
SceneDesc load_scene_desc(const std::string& path, bool strict = false);
// Prints each warning as `warning: ...` on stderr.
void print_warnings(const std::vector<std::string>& warnings);

} // namespace illum::cli
