// The realistic camera from scene files: its parameters, the lens file resolved against the scene's
// folder, positioned errors for a missing or malformed lens or aperture file, and `illum render` on the
// test scene.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "illum/camera/realistic_camera.h"
#include "illum/image/image_io.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "lens_support.h"

namespace illum {
namespace {

namespace fs = std::filesystem;

std::string scene_with(const std::string& camera_params) {
    return "Film \"rgb\" \"integer xresolution\" [48] \"integer yresolution\" [32]\n"
           "Camera \"realistic\" " +
           camera_params + "\nWorldBegin\nShape \"sphere\" \"float radius\" [1]\n";
}

std::unique_ptr<Scene> build(const std::string& text) {
    return build_scene(parse_pbrt_string(text, "s.pbrt", "."));
}

class RealisticScene : public testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("illum-lens-" + std::to_string(::getpid()) + "-" +
                                            testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(RealisticScene, BuildsARealisticCamera) {
    ILLUM_REQUIRE_DGAUSS();
    auto scene = build(scene_with(fmt::format("\"string lensfile\" \"{}\" \"float aperturediameter\" [4] "
                                              "\"float focusdistance\" [3] \"string aperture\" \"star\"",
                                              test::dgauss_path())));
    auto* cam = dynamic_cast<const RealisticCamera*>(scene->camera.get());
    ASSERT_TRUE(cam);
    EXPECT_TRUE(cam->is_dispersive());
    EXPECT_NEAR(cam->lens().interfaces()[5].aperture_radius, 2e-3, 1e-12);
    EXPECT_NEAR(cam->film_width(), 0.035 / std::sqrt(1 + sqr(32.0 / 48)), 1e-9); // default 35 mm diagonal
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
}

TEST_F(RealisticScene, LensFileIsRelativeToTheSceneFile) {
    ILLUM_REQUIRE_DGAUSS();
    fs::create_directories(dir_ / "scene" / "lenses");
    fs::copy_file(test::dgauss_path(), dir_ / "scene" / "lenses" / "dg.dat");
    std::ofstream(dir_ / "scene" / "s.pbrt") << scene_with("\"string lensfile\" \"lenses/dg.dat\"");
    auto scene = build_scene(parse_pbrt_file((dir_ / "scene" / "s.pbrt").string()));
    EXPECT_TRUE(dynamic_cast<const RealisticCamera*>(scene->camera.get()));
}

void expect_build_error(const std::string& text, const std::string& where, const std::string& phrase) {
    try {
        build(text);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.where().to_string(), where) << e.what();
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
}

TEST_F(RealisticScene, ErrorsArePositioned) {
    // The missing file is reported at its parameter (line 2, column 20), with every other missing file.
    expect_build_error(scene_with("\"string lensfile\" \"no/such.dat\""), "s.pbrt:2:20",
                       "cannot read lens file \"no/such.dat\"");
    expect_build_error(scene_with(""), "s.pbrt:2:1", "needs \"string lensfile\"");
    // A malformed lens file: its own line and column.
    fs::path bad = dir_ / "bad.dat";
    std::ofstream(bad) << "# r t n a\n10 2 1.5\n";
    expect_build_error(scene_with("\"string lensfile\" \"" + bad.string() + "\""), bad.string() + ":2:1",
                       "4 numbers");
    ILLUM_REQUIRE_DGAUSS();
    std::string lens = "\"string lensfile\" \"" + test::dgauss_path() + "\" ";
    const std::string next = fmt::format("s.pbrt:2:{}", 20 + lens.size()); // the parameter after it
    expect_build_error(scene_with(lens + "\"string aperture\" \"nothere.png\""), next,
                       "cannot read aperture image");
    expect_build_error(scene_with(lens + "\"float focusdistance\" [0.1]"), "s.pbrt:2:1", "too short");
    expect_build_error(scene_with(lens + "\"float aperturediameter\" [-1]"), next, "positive");
}

TEST_F(RealisticScene, TooLargeApertureIsClampedWithAWarning) {
    ILLUM_REQUIRE_DGAUSS();
    auto scene = build(
        scene_with("\"string lensfile\" \"" + test::dgauss_path() + "\" \"float aperturediameter\" [40]"));
    auto* cam = dynamic_cast<const RealisticCamera*>(scene->camera.get());
    ASSERT_TRUE(cam);
    EXPECT_NEAR(cam->lens().interfaces()[5].aperture_radius, 17.1e-3 / 2, 1e-12);
    ASSERT_EQ(scene->warnings.size(), 1u);
    EXPECT_NE(scene->warnings[0].find("clamped"), std::string::npos) << scene->warnings[0];
    BuildOptions strict;
    strict.strict = true;
    EXPECT_THROW(build_scene(parse_pbrt_string(scene_with("\"string lensfile\" \"" + test::dgauss_path() +
                                                          "\" \"float aperturediameter\" [40]"),
                                               "s.pbrt", "."),
                             strict),
                 Error);
}

TEST_F(RealisticScene, AnApertureImageStopsTheLens) {
    ILLUM_REQUIRE_DGAUSS();
    Image im(8, 8, Color3(1.0f));
    write_image(im, (dir_ / "stop.pfm").string());
    std::ofstream(dir_ / "s.pbrt") << scene_with("\"string lensfile\" \"" + test::dgauss_path() +
                                                 "\" \"string aperture\" \"stop.pfm\"");
    auto scene = build_scene(parse_pbrt_file((dir_ / "s.pbrt").string()));
    EXPECT_TRUE(dynamic_cast<const RealisticCamera*>(scene->camera.get()));
}

// `illum render` on tests/camera/data/realistic-dgauss.pbrt, whose lens path assumes the default layout.
TEST_F(RealisticScene, IllumRendersTheTestScene) {
    fs::path scene = fs::path(ILLUM_SOURCE_DIR) / "tests" / "camera" / "data" / "realistic-dgauss.pbrt";
    if (!fs::exists(scene.parent_path() / "../../../../shared/data/lenses/dgauss-50mm.dat"))
        GTEST_SKIP() << "the shared folder is not beside the source tree";
    std::string cmd = fmt::format("cd '{}' && '{}' render '{}' --spp 2 -o lens.exr > out.txt 2> err.txt",
                                  dir_.string(), ILLUM_CLI_PATH, scene.string());
    int status = std::system(cmd.c_str());
    std::ifstream err(dir_ / "err.txt");
    std::string err_text((std::istreambuf_iterator<char>(err)), {});
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err_text;
    EXPECT_EQ(err_text.find("warning"), std::string::npos) << err_text;
    Image im = read_image((dir_ / "lens.exr").string());
    EXPECT_EQ(im.width(), 96);
    EXPECT_GT(im.channel_mean()[0], 0);
    EXPECT_FALSE(im.has_non_finite());
}

} // namespace
} // namespace illum
