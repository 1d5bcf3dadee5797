// The launcher `illum` and its two builds (apps/launcher/launcher.cpp, CMakeLists.txt): ILLUM_ISA picks a
// build by name, the automatic choice names a level the processor has, bad settings and a launcher without
// its builds give one-line errors, and both builds render the same images bit for bit (no fused
// multiply-adds are formed in the x86-64-v3 build), for the path tracer in RGB and spectral mode, BDPT,
// and the coffee maker's layered, dielectric and conductor materials.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;

using cli_support::CliRun;
using cli_support::read_bytes;
using cli_support::run_in;

class IsaLauncher : public testing::Test {
protected:
    void SetUp() override {
        if (!ILLUM_HAS_V3) GTEST_SKIP() << "built without the x86-64-v3 copy (ILLUM_X86_64_V3 off)";
        dir_ = cli_support::fresh_test_folder("isa");
    }
    void TearDown() override {
        if (!dir_.empty()) fs::remove_all(dir_);
    }

    // illum with ILLUM_ISA set to `isa` ("" leaves it unset).
    CliRun illum_as(const std::string& isa, const std::string& args, const fs::path& dir) {
        std::string command = isa.empty() ? "env -u ILLUM_ISA '" : "ILLUM_ISA=" + isa + " '";
        command.append(ILLUM_CLI_PATH).append("' ").append(args);
        return run_in(command, dir);
    }

    // Whether this processor runs the x86-64-v3 build (the launcher refuses it otherwise).
    bool has_v3() { return illum_as("x86-64-v3", "--version", dir_).exit_code == 0; }

    fs::path dir_;
};

TEST_F(IsaLauncher, NamesTheBuildItStarts) {
    CliRun base = illum_as("x86-64", "--version", dir_);
    EXPECT_EQ(base.exit_code, 0) << base.err;
    EXPECT_NE(base.out.find("illum " ILLUM_VERSION " (x86-64)"), std::string::npos) << base.out;

    CliRun v3 = illum_as("x86-64-v3", "--version", dir_);
    if (v3.exit_code == 0) {
        EXPECT_NE(v3.out.find("(x86-64-v3)"), std::string::npos) << v3.out;
    } else {
        EXPECT_EQ(v3.exit_code, 2);
        EXPECT_NE(v3.err.find("lacks part of x86-64-v3"), std::string::npos) << v3.err;
    }
    // Unset or "auto": the best level the processor has.
    for (const char* isa : {"", "auto"}) {
        CliRun a = illum_as(isa, "--version", dir_);
        EXPECT_EQ(a.exit_code, 0) << a.err;
        EXPECT_NE(a.out.find(v3.exit_code == 0 ? "(x86-64-v3)" : "(x86-64)"), std::string::npos) << a.out;
    }
}

TEST_F(IsaLauncher, BadSettingsAreOneLineErrors) {
    CliRun bad = illum_as("avx9000", "--version", dir_);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err, "error: illum: ILLUM_ISA must be x86-64, x86-64-v3 or auto, not avx9000\n");

    // The launcher copied away from its builds.
    fs::copy_file(ILLUM_CLI_PATH, dir_ / "illum");
    CliRun alone = run_in("env -u ILLUM_ISA ./illum --version", dir_);
    EXPECT_EQ(alone.exit_code, 2);
    EXPECT_EQ(alone.err.rfind("error: illum: cannot start ", 0), 0u) << alone.err;
    EXPECT_NE(alone.err.find("illum-x86-64"), std::string::npos) << alone.err;
    EXPECT_TRUE(alone.out.empty());
}

TEST_F(IsaLauncher, BothBuildsRenderTheSameBits) {
    if (!has_v3()) GTEST_SKIP() << "this processor lacks x86-64-v3: only the baseline build runs here";
    struct Case {
        std::string name, args;
    };
    std::vector<Case> cases = {
        {"path-rgb", "render --resolution 48x48 --spp 4 --threads 2"},
        {"path-spectral", "render --resolution 48x48 --spp 4 --threads 2 --spectral"},
        {"bdpt-spectral", "render --resolution 48x48 --spp 2 --threads 2 --spectral --integrator bdpt"},
    };
    const fs::path coffee = fs::path(ILLUM_SHARED_DIR) / "scenes/coffee/test.pbrt";
    if (fs::exists(coffee))
        cases.push_back(
            {"coffee", "render '" + coffee.string() + "' --resolution 40x50 --spp 2 --threads 2"});
    else
        std::printf("ILLUM_SHARED_DIR has no scenes/coffee: the coffee maker's case is skipped\n");
    for (const Case& c : cases) {
        std::string bytes[2];
        int i = 0;
        for (const char* isa : {"x86-64", "x86-64-v3"}) {
            const std::string out = (dir_ / (c.name + "-" + isa + ".pfm")).string();
            CliRun r = illum_as(isa, c.args + " --quiet -o '" + out + "'", dir_);
            ASSERT_EQ(r.exit_code, 0) << c.name << " " << isa << ": " << r.err;
            bytes[i++] = read_bytes(out);
        }
        ASSERT_FALSE(bytes[0].empty()) << c.name;
        EXPECT_TRUE(bytes[0] == bytes[1]) << c.name << ": the two builds' images differ";
    }
}

} // namespace
