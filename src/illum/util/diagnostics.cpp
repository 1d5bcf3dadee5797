#include "illum/util/diagnostics.h"

#include <algorithm>

namespace illum {

void Diagnostics::unsupported(const SourceLocation& loc, const std::string& what) {
    if (strict_) throw Error(loc, what + " (unsupported; --strict)");
    std::string w = loc.file.empty() ? what : loc.to_string() + ": " + what;
    if (std::find(warnings_.begin(), warnings_.end(), w) == warnings_.end()) warnings_.push_back(w);
}

void Diagnostics::missing_file(const SourceLocation& loc, const std::string& message) {
    missing_.emplace_back(loc, message);
}

void Diagnostics::throw_if_files_missing() const {
    if (missing_.empty()) return;
    if (missing_.size() == 1) throw missing_.front();
    std::string all = std::to_string(missing_.size()) + " files cannot be read:";
    for (const Error& e : missing_) all += "\n  " + std::string(e.what());
    throw Error(all); // each line carries its own position
}

} // namespace illum
