// The modules the program loads from its own directory when it needs them (apps/plugins: illum-http.so for
// `render --serve`, illum-mpi.so under an MPI launcher): a program copied without them still runs
// everything else, and asking for the missing part is a one-line error naming the module, exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;
using cli_support::CliRun;
using cli_support::run_in;

class ModulesCli : public testing::Test {
protected:
    void SetUp() override {
        dir_ = cli_support::fresh_test_folder("modules");
        // The program (the launcher and its builds, or the one build) without the modules beside it.
        const fs::path cli = ILLUM_CLI_PATH;
        for (const char* name : {"illum", "illum-x86-64", "illum-x86-64-v3"})
            if (fs::exists(cli.parent_path() / name)) fs::copy_file(cli.parent_path() / name, dir_ / name);
        ASSERT_TRUE(fs::exists(dir_ / cli.filename()));
        program_ = (dir_ / cli.filename()).string();
    }
    void TearDown() override {
        if (!dir_.empty()) fs::remove_all(dir_);
    }
    fs::path dir_;
    std::string program_;
};

TEST_F(ModulesCli, RendersWithoutThem) {
    CliRun r = run_in("'" + program_ + "' render --resolution 8x8 --spp 1 -q -o out.exr", dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.exr"));
}

TEST_F(ModulesCli, PreviewWithoutItsModuleIsAnError) {
    CliRun r = run_in("'" + program_ + "' render --resolution 8x8 --spp 1 -q --serve 0 -o out.exr", dir_);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("error: cannot serve the preview: cannot load ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("illum-http.so"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

TEST_F(ModulesCli, MpiLaunchWithoutItsModuleIsAnError) {
    if (std::string(ILLUM_MPIEXEC).empty()) GTEST_SKIP() << "built without MPI";
    // What Open MPI's launcher sets: the program takes itself for a rank and needs the MPI module.
    CliRun r = run_in("OMPI_COMM_WORLD_SIZE=1 '" + program_ + "' --version", dir_);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("error: an MPI launcher started illum, but its MPI module did not load: ", 0), 0u)
        << r.err;
    EXPECT_NE(r.err.find("illum-mpi.so"), std::string::npos) << r.err;
}

} // namespace
