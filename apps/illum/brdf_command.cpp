// `illum brdf`: placeholder until the reflection-model tools land (issue 3).
#include "commands.h"

namespace illum::cli {
void add_brdf_command(CLI::App&) {}
} // namespace illum::cli
