// `illum photons` writes a PLY point cloud of one SPPM iteration's photons, and scene files' Integrator
// "sppm" renders with photon mapping (not the path tracer's fallback warning).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;

using cli_support::read_bytes;

class PhotonsCli : public testing::Test {
protected:
    void SetUp() override {
        dir_ = cli_support::fresh_test_folder("photons");
        std::ofstream(dir_ / "scene.pbrt") << R"(
Integrator "sppm" "float radius" [0.2] "integer maxdepth" [4] "integer photonsperiteration" [2000]
LookAt 0 -4 2  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
Sampler "sobol" "integer pixelsamples" [2]
WorldBegin
LightSource "point" "rgb I" [3 3 3] "point3 from" [0 0 2.5]
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "trianglemesh" "point3 P" [-3 -3 0 3 -3 0 3 3 0 -3 3 0] "integer indices" [0 1 2 0 2 3]
)";
    }
    void TearDown() override { fs::remove_all(dir_); }
    cli_support::CliRun illum(const std::string& args) { return cli_support::illum(args, dir_); }
    fs::path dir_;
};

// The header names the vertex count and properties; the body holds exactly that many 37-byte records
// (nine floats and a byte). A 6 × 6 floor 2.5 below a point light subtends 4 asin(9 / 15.25) = 2.52 sr, 20%
// of the sphere: ~200 of 1000 photons land, once (what the floor reflects escapes upwards).
TEST_F(PhotonsCli, WritesAPlyPointCloud) {
    cli_support::CliRun r = illum("photons scene.pbrt -o photons.ply --count 1000");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::string ply = read_bytes(dir_ / "photons.ply");
    ASSERT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    auto at = ply.find("element vertex ");
    ASSERT_NE(at, std::string::npos);
    long n = std::stol(ply.substr(at + 15));
    EXPECT_GT(n, 170);
    EXPECT_LT(n, 230);
    for (const char* p :
         {"property float x", "property float dx", "property float red", "property uchar bounce"})
        EXPECT_NE(ply.find(p), std::string::npos) << p;
    auto body = ply.find("end_header\n") + 11;
    EXPECT_EQ(ply.size() - body, std::size_t(n) * 37);
}

TEST_F(PhotonsCli, RefusesAnotherExtension) {
    cli_support::CliRun r = illum("photons scene.pbrt -o photons.txt");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(".ply"), std::string::npos) << r.err;
}

TEST_F(PhotonsCli, SceneIntegratorSppmRendersWithoutFallback) {
    cli_support::CliRun r = illum("render scene.pbrt -o out.exr");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("rendered with \"path\""), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.exr"));
    cli_support::CliRun r2 = illum("render scene.pbrt --integrator sppm --spp 3 -o out2.exr");
    ASSERT_EQ(r2.exit_code, 0) << r2.err;
}

} // namespace
