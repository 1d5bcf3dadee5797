// `illum info` closes with the unsupported features a scene uses (issue 13: "the target is none"): one line
// per kind with its count and every position, or "unsupported features: none".
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;

using cli_support::CliRun;
using cli_support::illum;
using cli_support::write_text;

class InfoCli : public testing::Test {
protected:
    void SetUp() override { dir_ = cli_support::fresh_test_folder("info"); }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

const std::string film = "Film \"rgb\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n";

// The section after the warnings: from "unsupported features:" to the end of the output.
std::string section(const std::string& out) {
    std::size_t at = out.find("unsupported features:");
    return at == std::string::npos ? std::string() : out.substr(at);
}

TEST_F(InfoCli, ListsEachUnsupportedKindWithCountAndPositions) {
    // Two kinds: a builder-side option (one use) and a parameter nothing reads, on two materials (two uses
    // of one kind, at two positions).
    write_text(dir_ / "two.pbrt", "Option \"bool wavefront\" true\n" + film +
                                      "WorldBegin\n"
                                      "Material \"diffuse\" \"float bogus\" [1]\n"
                                      "Shape \"sphere\"\n"
                                      "Material \"diffuse\" \"float bogus\" [2]\n"
                                      "Shape \"sphere\"\n");
    CliRun r = illum("info two.pbrt", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::string s = section(r.out);
    ASSERT_FALSE(s.empty()) << r.out;
    EXPECT_EQ(s.find("unsupported features: 2 kinds, 3 uses\n"), 0u) << s;
    EXPECT_NE(s.find("  Option \"wavefront\" is not used: illum has one CPU renderer x1 at two.pbrt:1:8\n"),
              std::string::npos)
        << s;
    EXPECT_NE(s.find("  material \"diffuse\": parameter \"float bogus\" is not used x2 at two.pbrt:4:20, "
                     "two.pbrt:6:20\n"),
              std::string::npos)
        << s;
    // Nothing after the two kinds.
    int lines = 0;
    for (char c : s) lines += c == '\n';
    EXPECT_EQ(lines, 3) << s;
}

TEST_F(InfoCli, ParserWarningsAreListedToo) {
    write_text(dir_ / "moving.pbrt", film + "WorldBegin\nActiveTransform EndTime\nTranslate 1 0 0\n"
                                            "LightSource \"point\"\nShape \"sphere\"\n");
    CliRun r = illum("info moving.pbrt", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::string s = section(r.out);
    EXPECT_EQ(s.find("unsupported features: 1 kind, 1 use\n"), 0u) << r.out;
    EXPECT_NE(s.find("x1 at moving.pbrt:5:1\n"), std::string::npos) << s;
}

TEST_F(InfoCli, SaysNoneForAFullySupportedScene) {
    write_text(dir_ / "none.pbrt", film + "WorldBegin\nLightSource \"point\"\n"
                                          "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
                                          "Shape \"sphere\"\n");
    CliRun r = illum("info none.pbrt", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(section(r.out), "unsupported features: none\n") << r.out;
    EXPECT_NE(r.out.find("warnings    0\n"), std::string::npos) << r.out;
}

} // namespace
