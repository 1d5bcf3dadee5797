// Shared helpers of the image tests: a scratch folder and file byte access.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "illum/image/image.h"

namespace illum::test {

// A fresh folder under testing::TempDir(), removed with its contents at the end of the test.
class ScratchDir {
public:
    ScratchDir() {
        std::string pattern = testing::TempDir() + "illum_image_XXXXXX";
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }
    // Names of everything in the folder, sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    std::filesystem::path path_;
};

inline std::string file_contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

inline void write_contents(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A deterministic image with values spanning several decades and distinct channels.
inline Image test_image(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float base = std::ldexp(1.0f + 0.0137f * float(x * 7 + y * 3), (x + 2 * y) % 12 - 6);
            img(x, y) = {base, base * 0.731f + 0.01f * float(y), base * 1.29f + 1e-4f * float(x)};
        }
    return img;
}

} // namespace illum::test
