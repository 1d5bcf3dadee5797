// The Sampler directive through the command line: the scene's "seed" is used unless --seed is given, and
// --sampler picks any of pbrt-v4's samplers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_support.h"

namespace {

using namespace cli_support;


TEST(SamplerCli, SceneSeedUnlessSeedGiven) {
    const fs::path dir = fresh_test_folder("sampler");
    write_text(dir / "s.pbrt", R"(LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Sampler "zsobol" "integer pixelsamples" 2 "integer seed" 5
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
WorldBegin
LightSource "point" "rgb I" [1 1 1] "point3 from" [0 0 -3]
Material "diffuse"
Shape "sphere" "float radius" 1
)");
    CliRun a = illum("render s.pbrt -o a.exr --stats a.json --quiet", dir);
    CliRun b = illum("render s.pbrt --seed 5 -o b.exr --quiet", dir);
    CliRun c = illum("render s.pbrt --seed 6 -o c.exr --quiet", dir);
    CliRun d = illum("render s.pbrt --sampler pmj02bn -o d.exr --quiet", dir);
    CliRun e = illum("render s.pbrt --sampler metropolis -o e.exr --quiet", dir);
    for (const CliRun* r : {&a, &b, &c, &d}) ASSERT_EQ(r->exit_code, 0) << r->err;
    EXPECT_EQ(a.err.find("replaced"), std::string::npos) << a.err;
    EXPECT_EQ(nlohmann::json::parse(read_bytes(dir / "a.json"))["seed"], 5);
    // (zsobol's pixel offsets depend on the seed, and this scene's pixels on nothing else.)
    EXPECT_TRUE(read_bytes(dir / "a.exr") == read_bytes(dir / "b.exr"));
    EXPECT_FALSE(read_bytes(dir / "a.exr") == read_bytes(dir / "c.exr"));
    EXPECT_FALSE(read_bytes(dir / "a.exr") == read_bytes(dir / "d.exr"));
    EXPECT_EQ(e.exit_code, 2);
    EXPECT_NE(e.err.find("unknown sampler \"metropolis\""), std::string::npos) << e.err;
    fs::remove_all(dir);
}

} // namespace
