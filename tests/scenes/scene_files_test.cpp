// Scene files as users lay them out: file names resolved once against the scene's folder, pbrt-v4's
// ReverseOrientation on meshes with normals, and every unreadable file of a scene reported in one run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "illum/bsdf/lambert.h"
#include "illum/bsdf/merl.h"
#include "illum/image/image_io.h"
#include "test_support.h"

namespace illum {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary one, and the working directory restored afterwards.
class SceneFiles : public ::testing::Test {
protected:
    void SetUp() override {
        saved_ = fs::current_path();
        root_ = fs::temp_directory_path() / ("illum_scene_files_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "sub");
    }
    void TearDown() override {
        fs::current_path(saved_);
        fs::remove_all(root_);
    }
    void write(const fs::path& rel, const std::string& text) { std::ofstream(root_ / rel) << text; }
    fs::path root_, saved_;
};

constexpr const char* kHeader = R"(LookAt 0 0 3  0 0 0  0 1 0
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
)";

// `illum render sub/scene.pbrt` run from the folder above: the image texture, the spectrum file and the
// measured material's table all lie beside the scene and are named relative to it. (They were looked for
// at sub/sub/tex.png, sub/sub/refl.spd and ./m.binary.)
TEST_F(SceneFiles, FileNamesResolveOnceAgainstTheSceneFolder) {
    Image tex(4, 4);
    for (std::size_t i = 0; i < tex.pixel_count(); ++i) tex.data()[i] = Color3(0.5f);
    write_image(tex, (root_ / "sub" / "tex.png").string());
    write("sub/refl.spd", "400 0.25\n700 0.25\n");
    MerlTable::from_bxdf(LambertBxDF(SampledSpectrum(0.5f))).write((root_ / "sub" / "m.binary").string());
    // One scene per file, so each resolution is checked on its own.
    const char* uses[] = {
        R"(Texture "t" "spectrum" "imagemap" "string filename" "tex.png"
Material "diffuse" "texture reflectance" "t")",
        R"(Material "diffuse" "spectrum reflectance" "refl.spd")",
        R"(Material "merl" "string file" "m.binary")",
    };
    fs::current_path(root_);
    for (const char* use : uses) {
        SCOPED_TRACE(use);
        write("sub/scene.pbrt", std::string(kHeader) + use + "\nShape \"sphere\" \"float radius\" [0.2]\n");
        SceneDesc desc = parse_pbrt_file("sub/scene.pbrt");
        EXPECT_NO_THROW(build_scene(desc));
    }
}

// pbrt-v4's TriangleMesh negates given normals under ReverseOrientation, and a one-sided emitter emits
// on their side: seen from +z, a light whose normals point to +z is bright, reversed it is black.
TEST(ReverseOrientation, FlipsTheNormalsAMeshGives) {
    auto scene = [](bool reverse) {
        return std::string(kHeader) + (reverse ? "ReverseOrientation\n" : "") + R"(
AreaLightSource "diffuse" "rgb L" [2 2 2]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
    "normal N" [0 0 1 0 0 1 0 0 1 0 0 1]
)";
    };
    test::RenderSetup s;
    s.spp = 1;
    Color3 plain = test::render_pbrt(scene(false), s).image.channel_mean();
    Color3 reversed = test::render_pbrt(scene(true), s).image.channel_mean();
    EXPECT_NEAR(plain.g, 2, 1e-4);
    EXPECT_EQ(reversed.g, 0);
}

// Two missing PLY files, a missing texture image and a missing environment map: one error names all four,
// each at its parameter.
TEST_F(SceneFiles, EveryMissingFileIsReportedInOneRun) {
    write("scene.pbrt", std::string(kHeader) + R"(
Texture "t" "spectrum" "imagemap" "string filename" "nothere.png"
Shape "plymesh" "string filename" "gone-a.ply"
Shape "plymesh" "string filename" "gone-b.ply"
LightSource "infinite" "string filename" "sky.exr"
)");
    try {
        build_scene(parse_pbrt_file((root_ / "scene.pbrt").string()));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("4 files cannot be read"), std::string::npos) << what;
        for (const char* name : {"nothere.png", "gone-a.ply", "gone-b.ply", "sky.exr"})
            EXPECT_NE(what.find(name), std::string::npos) << name << " in " << what;
        EXPECT_NE(what.find("scene.pbrt:6:"), std::string::npos) << what;
        EXPECT_NE(what.find("scene.pbrt:8:"), std::string::npos) << what;
    }
}

} // namespace
} // namespace illum
