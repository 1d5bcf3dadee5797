#include "illum/scene/load.h"

#include <filesystem>
#include <fmt/core.h>

#include "illum/scene/builtin/builtin.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/util/error.h"

namespace illum {

SceneDesc load_scene_desc(const std::string& path, bool strict) {
    if (path.empty()) return builtin_cornell_box();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error(fmt::format("cannot open scene \"{}\": no such file", path));
    if (std::filesystem::is_directory(path, ec))
        throw Error(fmt::format("cannot open scene \"{}\": it is a directory", path));
    ParseOptions options;
    options.strict = strict;
    return parse_pbrt_file(path, options);
}

} // namespace illum
