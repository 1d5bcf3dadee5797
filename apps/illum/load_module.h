// Loading one of illum's optional modules (illum-mpi.so, illum-http.so) from the directory of the running
// program, the only place the build puts them.
#pragma once

#include <string>

namespace illum::plugin {

// How a module's own libraries are loaded: kept to the module (the HTTP server's OpenSSL), or made global
// (MPI: Open MPI built with loadable components dlopens them expecting libmpi's symbols in the global
// scope, as mpi4py loads it).
enum class ModuleScope { Local, Global };

// The address of `symbol` in the module `file_name` beside the program (loaded once, never unloaded), or
// null with `*error` saying why (the path and dlerror's message).
void* module_symbol(const char* file_name, const char* symbol, ModuleScope scope, std::string* error);

} // namespace illum::plugin
