// Loading one of illum's optional modules (illum-mpi.so, illum-http.so) from the directory of the running
// program, the only place the build puts them.
#pragma once

#include <string>

namespace illum::plugin {

// The address of `symbol` in the module `file_name` beside the program (loaded once, never unloaded), or
// null with `*error` saying why (the path and dlerror's message).
void* module_symbol(const char* file_name, const char* symbol, std::string* error);

} // namespace illum::plugin
