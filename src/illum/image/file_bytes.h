// Whole-file reads and atomic whole-file writes, with errors that name the file (DESIGN.md §3 "Output").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace illum {

// The bytes of a regular file. Throws illum::Error `cannot read "path": <reason>`.
std::vector<unsigned char> read_file_bytes(const std::string& path);

// Writes `bytes` to a temporary file `.name.tmp-<pid>-<counter>` in the folder of `path`, flushes it to
// disk and renames it over `path`, so readers see either the old file or the complete new one. On any
// failure the temporary is removed, `path` is left as it was, and illum::Error
// `cannot write "path": <reason>` is thrown. If `path` is a symbolic link, the link itself is replaced.
void write_file_atomically(const std::string& path, std::string_view bytes);

// The temporary name write_file_atomically uses next to `path` (exposed for tests).
std::string temporary_path_for(const std::string& path);

} // namespace illum
