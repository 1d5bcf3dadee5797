// What building a scene has to say besides its result: recognised but unsupported features (one warning
// each, an error under --strict) and the files it could not read (collected, so one run reports every
// missing file of a scene instead of one per run).
#pragma once

#include <string>
#include <vector>

#include "illum/util/error.h"

namespace illum {

// One use of a recognised but unsupported (or approximated, or ignored) feature: where the scene uses it
// and what illum does instead. Uses with the same `what` are one kind (`illum info` groups them).
struct UnsupportedUse {
    SourceLocation loc;
    std::string what;
};

// The uses of one kind of unsupported feature (one `what`), in the order met.
struct UnsupportedKind {
    std::string what;
    std::vector<SourceLocation> uses;
};
// Groups uses by their text, kinds in the order first met.
std::vector<UnsupportedKind> group_by_kind(const std::vector<UnsupportedUse>& uses);

class Diagnostics {
public:
    explicit Diagnostics(bool strict = false) : strict_(strict) {}

    bool strict() const { return strict_; }
    // A recognised feature that illum does not support: one warning per distinct text, or an error under
    // --strict. Each distinct (position, text) is also recorded as an UnsupportedUse.
    void unsupported(const SourceLocation& loc, const std::string& what);
    // A file that could not be read: recorded here; throw_if_files_missing() raises them all at once.
    void missing_file(const SourceLocation& loc, const std::string& message);
    bool files_missing() const { return !missing_.empty(); }
    // One Error listing every recorded missing file (positioned at the first); nothing when none.
    void throw_if_files_missing() const;

    const std::vector<std::string>& warnings() const { return warnings_; }
    // Warnings made elsewhere (the parser's, SceneDesc::warnings), placed first, and their uses.
    void add_warnings(const std::vector<std::string>& w, const std::vector<UnsupportedUse>& uses = {});
    // Every unsupported feature the scene uses, in the order met (the added ones first).
    const std::vector<UnsupportedUse>& unsupported_uses() const { return uses_; }

private:
    bool strict_ = false;
    std::vector<std::string> warnings_;
    std::vector<UnsupportedUse> uses_;
    std::vector<Error> missing_;
};

} // namespace illum
