// Shared helpers of the pbrt parser tests: temporary folders and checks of illum::Error messages.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "illum/util/error.h"

namespace illum::test {

// A fresh folder under the system temp dir, removed at scope exit.
class TempDir {
public:
    explicit TempDir(const std::string& tag) {
        static int counter = 0;
        path_ =
            std::filesystem::temp_directory_path() /
            ("illum_pbrt_test_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string path() const { return path_.string(); }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string write(const std::string& name, const std::string& content) const {
        std::string p = file(name);
        std::filesystem::create_directories(std::filesystem::path(p).parent_path());
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }

private:
    std::filesystem::path path_;
};

// Runs f, which must throw illum::Error whose text contains `where` (e.g. "bad.pbrt:3:7") and `phrase`.
template <class F>
void expect_error(F&& f, const std::string& where, const std::string& phrase) {
    try {
        f();
        ADD_FAILURE() << "no error thrown; expected \"" << where << "\" and \"" << phrase << "\"";
    } catch (const Error& e) {
        std::string what = e.what();
        EXPECT_NE(what.find(where), std::string::npos) << "position " << where << " not in: " << what;
        EXPECT_NE(what.find(phrase), std::string::npos) << "phrase \"" << phrase << "\" not in: " << what;
    }
}

inline bool shared_dir_exists() { return std::filesystem::is_directory(ILLUM_SHARED_DIR); }

} // namespace illum::test
