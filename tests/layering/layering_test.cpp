// Modules only include downward: the order is CMakeLists.txt's ILLUM_MODULES (bottom first), each module
// may include itself and the modules before it. A scan of every #include "illum/<module>/..." under
// src/illum, checked against that list, plus a synthetic tree that proves the scan reports an upward one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The module order from `set(ILLUM_MODULES a b c ...)` in CMakeLists.txt.
std::vector<std::string> module_order(const fs::path& cmakelists) {
    std::string text = read_text(cmakelists);
    std::smatch m;
    if (!std::regex_search(text, m, std::regex(R"(set\(ILLUM_MODULES([^)]*)\))"))) return {};
    std::istringstream words(m[1].str());
    std::vector<std::string> order;
    for (std::string w; words >> w;) order.push_back(w);
    return order;
}

// "file:line: a includes b (above it)" for every include that points up or to an unlisted module, and
// "module m is not in ILLUM_MODULES" for a folder the order does not name.
std::vector<std::string> layering_violations(const fs::path& root, const std::vector<std::string>& order) {
    std::map<std::string, int> rank;
    for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = int(i);
    std::vector<std::string> out;
    const std::regex include(R"(^\s*#\s*include\s*"illum/([a-z_0-9]+)/)");
    for (const auto& dir : fs::directory_iterator(root)) {
        if (!dir.is_directory()) continue;
        std::string module = dir.path().filename().string();
        if (!rank.count(module)) {
            out.push_back("module " + module + " is not in ILLUM_MODULES");
            continue;
        }
        for (const auto& f : fs::recursive_directory_iterator(dir.path())) {
            if (!f.is_regular_file()) continue;
            std::ifstream in(f.path());
            int n = 0;
            for (std::string line; std::getline(in, line);) {
                ++n;
                std::smatch m;
                if (!std::regex_search(line, m, include)) continue;
                std::string target = m[1].str();
                auto it = rank.find(target);
                if (it == rank.end() || it->second > rank[module])
                    out.push_back(fs::relative(f.path(), root).string() + ":" + std::to_string(n) + ": " +
                                  module + " includes " + target +
                                  (it == rank.end() ? " (not a module)" : " (above it)"));
            }
        }
    }
    return out;
}

TEST(Layering, ModulesOnlyIncludeDownward) {
    fs::path src = fs::path(ILLUM_SOURCE_DIR);
    std::vector<std::string> order = module_order(src / "CMakeLists.txt");
    ASSERT_GE(order.size(), 10u) << "no ILLUM_MODULES list in CMakeLists.txt";
    std::vector<std::string> v = layering_violations(src / "src" / "illum", order);
    std::string all;
    for (const auto& s : v) all += s + "\n";
    EXPECT_TRUE(v.empty()) << all;
}

TEST(Layering, TheScanFindsAnUpwardInclude) {
    fs::path root = fs::temp_directory_path() / ("illum_layering_" + std::to_string(::getpid()));
    fs::create_directories(root / "low");
    fs::create_directories(root / "high");
    std::ofstream(root / "high" / "a.h") << "#include \"illum/low/b.h\"\n";
    std::ofstream(root / "low" / "b.h") << "// fine\n  #include \"illum/high/a.h\"\n";
    auto v = layering_violations(root, {"low", "high"});
    ASSERT_EQ(v.size(), 1u);
    EXPECT_EQ(v[0], (fs::path("low") / "b.h").string() + ":2: low includes high (above it)");
    fs::create_directories(root / "stray");
    EXPECT_EQ(layering_violations(root, {"low", "high"}).size(), 2u);
    fs::remove_all(root);
}

} // namespace
