// The one exception type for user-facing errors (DESIGN.md §3): it carries the source position of the
// problem when there is one, so the CLI can print `error: scene.pbrt:12:5: message` and exit 2.
#pragma once

#include <stdexcept>
#include <string>

namespace illum {

struct SourceLocation {
    std::string file;
    int line = 0;   // 1-based; 0 when unknown
    int column = 0; // 1-based; 0 when unknown

    std::string to_string() const {
        if (file.empty()) return {};
        if (line == 0) return file;
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message), message_(message) {}
    Error(SourceLocation where, const std::string& message)
        : std::runtime_error(where.file.empty() ? message : where.to_string() + ": " + message),
          where_(std::move(where)), message_(message) {}

    const SourceLocation& where() const { return where_; }
    const std::string& message() const { return message_; }

private:
    SourceLocation where_;
    std::string message_;
};

} // namespace illum
