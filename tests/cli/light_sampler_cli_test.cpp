// --light-sampler overrides the scene's "lightsampler"; an unknown name is refused before rendering, and
// the scene's own unknown name is an error at its position.
#include <gtest/gtest.h>

#include "cli_support.h"

namespace {

using namespace cli_support;

TEST(LightSamplerCli, OverridesTheSceneAndRefusesUnknownNames) {
    const fs::path dir = fresh_test_folder("light_sampler");
    // Two point lights of different power, either side of the sphere: power picks them 1:9, the BVH by
    // their importance at each point, so the two images differ (in noise).
    const std::string scene = R"(LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Sampler "independent" "integer pixelsamples" 4
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
Integrator "path" "string lightsampler" "{}"
WorldBegin
LightSource "point" "rgb I" [1 1 1] "point3 from" [-2 0 -3]
LightSource "point" "rgb I" [9 9 9] "point3 from" [2 0 -3]
Material "diffuse"
Shape "sphere" "float radius" 1
)";
    auto with = [&](const std::string& name) {
        std::string s = scene;
        s.replace(s.find("{}"), 2, name);
        return s;
    };
    write_text(dir / "power.pbrt", with("power"));
    write_text(dir / "bvh.pbrt", with("bvh"));
    write_text(dir / "bad.pbrt", with("nearest"));
    CliRun a = illum("render power.pbrt -o a.exr --quiet", dir);
    CliRun b = illum("render bvh.pbrt --light-sampler power -o b.exr --quiet", dir);
    CliRun c = illum("render bvh.pbrt -o c.exr --quiet", dir);
    CliRun d = illum("render bvh.pbrt --light-sampler nearest -o d.exr --quiet", dir);
    CliRun e = illum("render bad.pbrt -o e.exr --quiet", dir);
    for (const CliRun* r : {&a, &b, &c}) ASSERT_EQ(r->exit_code, 0) << r->err;
    EXPECT_TRUE(read_bytes(dir / "a.exr") == read_bytes(dir / "b.exr"));
    EXPECT_FALSE(read_bytes(dir / "a.exr") == read_bytes(dir / "c.exr"));
    EXPECT_NE(d.exit_code, 0);
    EXPECT_NE(d.err.find("nearest"), std::string::npos) << d.err;
    EXPECT_FALSE(fs::exists(dir / "d.exr"));
    EXPECT_NE(e.exit_code, 0);
    EXPECT_NE(e.err.find("bad.pbrt:5:"), std::string::npos) << e.err;
    EXPECT_NE(e.err.find("unknown light sampler \"nearest\""), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(dir / "e.exr"));
    fs::remove_all(dir);
}

} // namespace
