#include "scene_loading.h"

#include <cstdio>
#include <fmt/core.h>

namespace illum::cli {

void print_warnings(const std::vector<std::string>& warnings) {
    for (const auto& w : warnings) fmt::print(stderr, "warning: {}\n", w);
}

} // namespace illum::cli
