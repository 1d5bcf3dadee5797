// Loading a scene description by file name: a pbrt-v4 file, or the built-in Cornell box when the name is
// empty. The CLI's subcommands and the Python module load scenes through this one function.
#pragma once

#include <string>

#include "illum/scene/scene_desc.h"

namespace illum {

// `strict` (--strict): the parser's warnings are errors, as the builder's are with BuildOptions::strict.
// Throws illum::Error for a missing file, a directory, or (with file:line:column) a parse error.
SceneDesc load_scene_desc(const std::string& path, bool strict = false);

} // namespace illum
