// What building a scene has to say besides its result: recognised but unsupported features (one warning
// each, an error under --strict) and the files it could not read (collected, so one run reports every
// missing file of a scene instead of one per run).
#pragma once

#include <string>
#include <vector>

#include "illum/util/error.h"

namespace illum {

class Diagnostics {
public:
    explicit Diagnostics(bool strict = false) : strict_(strict) {}

    bool strict() const { return strict_; }
    // A recognised feature that illum does not support: one warning per distinct text, or an error under
    // --strict.
    void unsupported(const SourceLocation& loc, const std::string& what);
    // A file that could not be read: recorded here; throw_if_files_missing() raises them all at once.
    void missing_file(const SourceLocation& loc, const std::string& message);
    bool files_missing() const { return !missing_.empty(); }
    // One Error listing every recorded missing file (positioned at the first); nothing when none.
    void throw_if_files_missing() const;

    const std::vector<std::string>& warnings() const { return warnings_; }
    void add_warnings(const std::vector<std::string>& w) {
        warnings_.insert(warnings_.begin(), w.begin(), w.end());
    }

private:
    bool strict_ = false;
    std::vector<std::string> warnings_;
    std::vector<Error> missing_;
};

} // namespace illum
