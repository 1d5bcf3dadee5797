// Integrator "vcm" from a scene file and from --integrator: it renders (the stats line names its grid's
// memory), `illum render --help` lists it and its parameters, and a bad parameter is a positioned error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;

const char* kScene = R"(Integrator "vcm" "float radius" [0.05] "integer maxdepth" [4] "string mode" "{mode}"
LookAt 0 -4 2  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "sobol" "integer pixelsamples" [2]
WorldBegin
LightSource "point" "rgb I" [3 3 3] "point3 from" [0 0 2.5]
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
)";

class VcmCli : public testing::Test {
protected:
    void SetUp() override { dir_ = cli_support::fresh_test_folder("vcm"); }
    void TearDown() override { fs::remove_all(dir_); }
    void write_scene(const std::string& mode) {
        std::string s = kScene;
        s.replace(s.find("{mode}"), 6, mode);
        std::ofstream(dir_ / "scene.pbrt") << s;
    }
    cli_support::CliRun illum(const std::string& args) { return cli_support::illum(args, dir_); }
    fs::path dir_;
};

TEST_F(VcmCli, RendersFromTheSceneFile) {
    write_scene("vcm");
    cli_support::CliRun r = illum("render scene.pbrt -o out.exr");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("vcm: 2 iterations of 256 light subpaths"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("grid"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.exr"));
}

TEST_F(VcmCli, HelpListsIt) {
    cli_support::CliRun r = illum("render --help");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* s : {"sppm or vcm", "photonsperiteration", "misheuristic"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
}

TEST_F(VcmCli, BadModeIsAPositionedError) {
    write_scene("photons");
    cli_support::CliRun r = illum("render scene.pbrt -o out.exr");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("scene.pbrt:1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("mode must be"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

} // namespace
