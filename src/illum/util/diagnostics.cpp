#include "illum/util/diagnostics.h"

#include <algorithm>

namespace illum {

namespace {

bool same_use(const UnsupportedUse& a, const UnsupportedUse& b) {
    return a.what == b.what && a.loc.file == b.loc.file && a.loc.line == b.loc.line &&
           a.loc.column == b.loc.column;
}

} // namespace

void Diagnostics::unsupported(const SourceLocation& loc, const std::string& what) {
    if (strict_) throw Error(loc, what + " (unsupported; --strict)");
    std::string w = loc.file.empty() ? what : loc.to_string() + ": " + what;
    if (std::find(warnings_.begin(), warnings_.end(), w) == warnings_.end()) warnings_.push_back(w);
    UnsupportedUse use{loc, what};
    if (std::none_of(uses_.begin(), uses_.end(), [&](const UnsupportedUse& u) { return same_use(u, use); }))
        uses_.push_back(std::move(use));
}

void Diagnostics::add_warnings(const std::vector<std::string>& w, const std::vector<UnsupportedUse>& uses) {
    warnings_.insert(warnings_.begin(), w.begin(), w.end());
    uses_.insert(uses_.begin(), uses.begin(), uses.end());
}

std::vector<UnsupportedKind> group_by_kind(const std::vector<UnsupportedUse>& uses) {
    std::vector<UnsupportedKind> kinds;
    for (const UnsupportedUse& u : uses) {
        auto k = std::find_if(kinds.begin(), kinds.end(),
                              [&](const UnsupportedKind& x) { return x.what == u.what; });
        if (k == kinds.end()) k = kinds.insert(kinds.end(), UnsupportedKind{u.what, {}});
        k->uses.push_back(u.loc);
    }
    return kinds;
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
