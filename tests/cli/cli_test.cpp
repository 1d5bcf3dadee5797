// End-to-end runs of the illum executable (DESIGN.md §4.5): the built-in scene renders; bad input gives a
// one-line error and a non-zero exit, and leaves existing outputs untouched; the same seed gives the same
// bytes whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "cli_support.h"
#include "illum/image/image_io.h"

namespace {

namespace fs = std::filesystem;

using cli_support::CliRun;
using cli_support::illum;
using cli_support::read_bytes;
using cli_support::write_text;

int count_lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

class Cli : public testing::Test {
protected:
    void SetUp() override { dir_ = cli_support::fresh_test_folder("cli"); }
    void TearDown() override { fs::remove_all(dir_); }

    // A one-line error on stderr, `error: ...` containing `phrase`, and exit code 2.
    void expect_error(const CliRun& r, const std::string& phrase) {
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(count_lines(r.err), 1) << r.err;
        EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(phrase), std::string::npos) << "expected \"" << phrase << "\" in: " << r.err;
    }
    fs::path dir_;
};

TEST_F(Cli, VersionAndHelp) {
    CliRun v = illum("--version", dir_);
    EXPECT_EQ(v.exit_code, 0);
    EXPECT_NE(v.out.find("illum " ILLUM_VERSION), std::string::npos) << v.out;
    for (const char* sub : {"render", "bench", "brdf", "diff"}) {
        CliRun h = illum(std::string(sub) + " --help", dir_);
        EXPECT_EQ(h.exit_code, 0) << sub;
        EXPECT_NE(h.out.find("Usage"), std::string::npos) << sub << ": " << h.out;
    }
}

TEST_F(Cli, BenchReportsTheRoundWithTheMedianRatio) {
    CliRun r = illum("bench --json --rounds 3 --resolution 24x24 --spp 2 --rays 20000 --threads 1", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["ratios"].size(), 3u);
    std::vector<double> ratios = j["ratios"].get<std::vector<double>>();
    for (double q : ratios) EXPECT_GT(q, 0.0);
    std::sort(ratios.begin(), ratios.end());
    EXPECT_EQ(j["ratio"].get<double>(), ratios[1]);
    // The reported figures are that round's own: its ratio is its path tracer's rate over its Embree rate.
    EXPECT_NEAR(j["path_rays_per_second"].get<double>() /
                    j["embree_incoherent_rays_per_second"].get<double>(),
                ratios[1], 1e-9 * ratios[1]);
    expect_error(illum("bench --rounds 0", dir_), "--rounds");
}

TEST_F(Cli, BuiltInSceneRendersToEveryFormat) {
    CliRun r = illum(
        "render --resolution 32x32 --spp 2 -o a.png -o a.exr -o a.pfm -o a.hdr --stats s.json --quiet", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"a.png", "a.exr", "a.pfm", "a.hdr", "s.json"})
        EXPECT_GT(fs::file_size(dir_ / f), 100u) << f;
    auto stats = nlohmann::json::parse(read_bytes(dir_ / "s.json"));
    for (const char* key : {"seconds", "samples", "rays", "rays_per_second", "threads", "version", "spp"})
        EXPECT_TRUE(stats.contains(key)) << key;
    EXPECT_EQ(stats["spp"], 2);
    EXPECT_EQ(stats["samples"], 32 * 32 * 2);
    // No temporary files are left behind.
    for (auto& e : fs::directory_iterator(dir_))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST_F(Cli, DefaultOutputIsTheFilmFileName) {
    // Without -o the image goes to the film's file name, as in pbrt: cornell-box.png for the built-in scene.
    CliRun small = illum("render --resolution 16x16 --spp 1 --quiet", dir_);
    EXPECT_EQ(small.exit_code, 0) << small.err;
    EXPECT_TRUE(fs::exists(dir_ / "cornell-box.png"));
}

TEST_F(Cli, SameSeedSameBytesWhateverTheThreadCount) {
    CliRun r1 = illum("render --resolution 64x48 --spp 4 --seed 7 --threads 1 -o t1.exr --quiet", dir_);
    CliRun r2 = illum("render --resolution 64x48 --spp 4 --seed 7 --threads 2 -o t2.exr --quiet", dir_);
    CliRun r3 = illum("render --resolution 64x48 --spp 4 --seed 8 --threads 2 -o t3.exr --quiet", dir_);
    ASSERT_EQ(r1.exit_code, 0) << r1.err;
    ASSERT_EQ(r2.exit_code, 0) << r2.err;
    ASSERT_EQ(r3.exit_code, 0) << r3.err;
    EXPECT_EQ(read_bytes(dir_ / "t1.exr"), read_bytes(dir_ / "t2.exr"));
    EXPECT_NE(read_bytes(dir_ / "t1.exr"), read_bytes(dir_ / "t3.exr")) << "the seed changes the image";
}

TEST_F(Cli, TimeBudgetRendersWholePasses) {
    CliRun r = illum("render --resolution 32x32 --time 0.3 -o t.exr --stats t.json --quiet", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto stats = nlohmann::json::parse(read_bytes(dir_ / "t.json"));
    int spp = stats["spp"];
    EXPECT_GE(spp, 1);
    EXPECT_EQ(stats["samples"], 32 * 32 * spp) << "whole passes only";
    EXPECT_GE(double(stats["seconds"]), 0.3);
}

TEST_F(Cli, UnusedParametersWarnAndStrictRefuses) {
    write_text(dir_ / "u.pbrt", "Film \"rgb\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
                                "WorldBegin\nShape \"sphere\" \"float radius\" [1] \"float radiuss\" [2]\n");
    CliRun r = illum("render u.pbrt --spp 1 -o u.exr", dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: u.pbrt:3:35: shape \"sphere\": parameter \"float radiuss\" is not used"),
              std::string::npos)
        << r.err;
    expect_error(illum("render u.pbrt --spp 1 --strict -o v.exr", dir_), "u.pbrt:3:35:");
    EXPECT_FALSE(fs::exists(dir_ / "v.exr"));
}

// A scene that ends before WorldBegin would render nothing: it is an error at its end, as in pbrt-v4.
TEST_F(Cli, SceneWithoutWorldIsAnError) {
    write_text(dir_ / "empty.pbrt", "");
    expect_error(illum("render empty.pbrt -o x.exr", dir_),
                 "error: empty.pbrt:1:1: End of files before WorldBegin");
    write_text(dir_ / "options.pbrt", "Film \"rgb\" \"integer xresolution\" [8]\nCamera \"perspective\"\n");
    expect_error(illum("render options.pbrt -o x.exr", dir_),
                 "error: options.pbrt:3:1: End of files before WorldBegin");
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

// The parser's warnings (here: a moving light, which pbrt-v4 does not move either) are errors under
// --strict too, not only the builder's.
TEST_F(Cli, StrictRefusesParserWarnings) {
    write_text(dir_ / "blur.pbrt", "Film \"rgb\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
                                   "WorldBegin\nActiveTransform EndTime\nTranslate 1 0 0\n"
                                   "LightSource \"point\"\nShape \"sphere\"\n");
    CliRun r = illum("render blur.pbrt --spp 1 -o u.exr", dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: blur.pbrt:5:1: a moving light is not supported"), std::string::npos)
        << r.err;
    expect_error(illum("render blur.pbrt --spp 1 --strict -o v.exr", dir_),
                 "error: blur.pbrt:5:1: a moving light is not supported");
    EXPECT_FALSE(fs::exists(dir_ / "v.exr"));
    EXPECT_EQ(illum("info blur.pbrt", dir_).exit_code, 0);
    expect_error(illum("info blur.pbrt --strict", dir_), "error: blur.pbrt:5:1: a moving light");
}

// Media: `illum info` lists each medium and the shapes that bound it; a medium that was never made and a
// negative coefficient are positioned errors (exit 2), and no output is written.
TEST_F(Cli, MediaInfoAndErrors) {
    const std::string head = "Film \"rgb\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
                             "WorldBegin\n";
    write_text(dir_ / "fog.pbrt", head + "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
                                         "MediumInterface \"fog\" \"\"\nMaterial \"interface\"\n"
                                         "Shape \"sphere\"\n");
    CliRun info = illum("info fog.pbrt", dir_);
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("medium \"fog\": homogeneous"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("inside \"sphere\" at fog.pbrt:6:1"), std::string::npos) << info.out;
    EXPECT_EQ(illum("render fog.pbrt --spp 1 -o f.exr", dir_).exit_code, 0);

    write_text(dir_ / "undefined.pbrt", head + "MediumInterface \"smoke\" \"\"\nShape \"sphere\"\n");
    expect_error(illum("render undefined.pbrt --spp 1 -o u.exr", dir_),
                 "undefined.pbrt:3:1: medium \"smoke\" was never made");
    write_text(dir_ / "negative.pbrt",
               head + "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_s\" [1 -2 1]\n");
    expect_error(illum("render negative.pbrt --spp 1 -o n.exr", dir_), "negative.pbrt:3:");
    write_text(dir_ / "nan.pbrt",
               head + "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"float g\" [nan]\n");
    expect_error(illum("render nan.pbrt --spp 1 -o x.exr", dir_), "nan.pbrt:3:");
    for (const char* out : {"u.exr", "n.exr", "x.exr"}) EXPECT_FALSE(fs::exists(dir_ / out)) << out;
}

// The lines of `illum diff`'s table (up to the first line that is not a row), each of the same width.
void expect_aligned_table(const std::string& out) {
    std::istringstream in(out);
    std::string header, line;
    ASSERT_TRUE(std::getline(in, header));
    int rows = 0;
    while (std::getline(in, line) && line.rfind("excluded", 0) != 0) {
        EXPECT_EQ(line.size(), header.size()) << "misaligned row: \"" << line << "\" in\n" << out;
        ++rows;
    }
    EXPECT_EQ(rows, 7) << out;
}

// Pixels with Inf/NaN are left out of `illum diff`'s figures, counted, and the table stays aligned.
TEST_F(Cli, DiffExcludesNonFinitePixels) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    illum::Image a(2, 2, illum::Color3(1.0f)), b(2, 2, illum::Color3(1.0f));
    a(1, 0) = {inf, 1, 1};
    a(0, 1) = {nan, 2, 2};
    b(1, 1) = {-inf, 1, 1};
    illum::write_image(a, (dir_ / "a.pfm").string());
    illum::write_image(b, (dir_ / "b.pfm").string());
    CliRun r = illum("diff a.pfm b.pfm", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("excluded 2 pixels with Inf/NaN in a.pfm, 1 in b.pfm"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("inf"), std::string::npos) << r.out;
    expect_aligned_table(r.out);
    auto j = nlohmann::json::parse(illum("diff --json a.pfm b.pfm", dir_).out);
    EXPECT_EQ(j["nonfinite_pixels"]["image"], 2);
    EXPECT_EQ(j["nonfinite_pixels"]["reference"], 1);
    EXPECT_EQ(j["compared_pixels"], 1);
    EXPECT_DOUBLE_EQ(double(j["rmse"]["all"]), 0.0);

    // A reference channel of mean 0 gives an infinite mean difference: still in its column.
    illum::write_image(illum::Image(2, 2, illum::Color3(0, 1, 1)), (dir_ / "z.pfm").string());
    r = illum("diff a.pfm z.pfm", dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_aligned_table(r.out);
    EXPECT_NE(r.out.find("excluded 2 pixels with Inf/NaN in a.pfm, 0 in z.pfm"), std::string::npos) << r.out;
}

TEST_F(Cli, MissingSceneFile) {
    expect_error(illum("render nowhere.pbrt -o x.exr", dir_), "nowhere.pbrt");
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

TEST_F(Cli, UnknownOutputExtension) {
    write_text(dir_ / "x.xyz", "keep me");
    expect_error(illum("render --resolution 8x8 --spp 1 -o x.xyz", dir_), ".xyz");
    EXPECT_EQ(read_bytes(dir_ / "x.xyz"), "keep me");
}

TEST_F(Cli, BadSampleCounts) {
    for (const char* spp : {"0", "abc", "-3", "1.5"}) {
        expect_error(illum(std::string("render --resolution 8x8 --spp ") + spp + " -o x.exr", dir_),
                     std::string("--spp: must be a positive whole number, not \"") + spp + "\"");
        EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
    }
}

TEST_F(Cli, UnwritableOutputPath) {
    expect_error(illum("render --resolution 8x8 --spp 1 -o /nonexistent/dir/x.exr", dir_),
                 "/nonexistent/dir");
    fs::create_directory(dir_ / "adir");
    expect_error(illum("render --resolution 8x8 --spp 1 -o adir", dir_), "adir");
}

TEST_F(Cli, FailedRenderLeavesExistingOutputUntouched) {
    ASSERT_EQ(illum("render --resolution 16x16 --spp 1 -o keep.exr --quiet", dir_).exit_code, 0);
    std::string before = read_bytes(dir_ / "keep.exr");
    write_text(dir_ / "bad.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [1]\nShape \"teapot\"\n");
    expect_error(illum("render bad.pbrt -o keep.exr", dir_), "bad.pbrt:3:1: unknown shape type \"teapot\"");
    write_text(dir_ / "syntax.pbrt", "WorldBegin\nShape \"sphere\" \"float radius\" [1\n");
    CliRun r = illum("render syntax.pbrt -o keep.exr", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("syntax.pbrt:"), std::string::npos) << r.err;
    EXPECT_EQ(read_bytes(dir_ / "keep.exr"), before);
}

TEST_F(Cli, SceneErrorsNameFileLineColumn) {
    write_text(dir_ / "m.pbrt", "WorldBegin\n\nMaterial \"plastic-ish\"\nShape \"sphere\"\n");
    expect_error(illum("render m.pbrt -o x.exr", dir_), "m.pbrt:3:1: unknown material type \"plastic-ish\"");
    write_text(dir_ / "nan.pbrt", "Translate 0 nan 0\nWorldBegin\n");
    CliRun r = illum("render nan.pbrt -o x.exr", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("nan.pbrt:1:"), std::string::npos) << r.err;
    write_text(
        dir_ / "idx.pbrt",
        "WorldBegin\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 5]\n");
    expect_error(illum("render idx.pbrt -o x.exr", dir_), "idx.pbrt:2:");
}

} // namespace
