#include "load_module.h"

#include <dlfcn.h>
#include <filesystem>
#include <system_error>

namespace illum::plugin {

void* module_symbol(const char* file_name, const char* symbol, ModuleScope scope, std::string* error) {
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) {
        *error = "cannot find the running program (/proc/self/exe): " + ec.message();
        return nullptr;
    }
    const std::string path = (self.parent_path() / file_name).string();
    void* handle = dlopen(path.c_str(), RTLD_NOW | (scope == ModuleScope::Global ? RTLD_GLOBAL : RTLD_LOCAL));
    if (!handle) {
        const char* why = dlerror();
        *error = "cannot load " + path + ": " + (why ? why : "unknown error");
        return nullptr;
    }
    void* address = dlsym(handle, symbol);
    if (!address) {
        *error = path + " has no " + symbol;
        return nullptr;
    }
    return address;
}

} // namespace illum::plugin
