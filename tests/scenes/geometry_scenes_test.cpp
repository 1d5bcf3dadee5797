// The scenes of scenes/geometry (bilinear patches, Loop subdivision, plymesh displacement; compared with
// pbrt-v4 in docs/verification.md) build without a warning and render finite images.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace illum {
namespace {

TEST(GeometryScenes, BuildWithoutWarningsAndRender) {
    for (const char* name : {"bilinear-patches", "loopsubdiv", "displacement"}) {
        std::string path = std::string(ILLUM_SOURCE_DIR) + "/scenes/geometry/" + name + ".pbrt";
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        SceneDesc desc = parse_pbrt_file(path);
        desc.set_film_resolution(24, 18);
        auto scene = build_scene(desc);
        EXPECT_TRUE(scene->warnings.empty()) << name << ": " << scene->warnings.front();
        auto integrator = make_integrator(scene->request.integrator, *scene, scene->request.max_depth);
        RenderOptions opt;
        opt.spp = 2;
        opt.quiet = true;
        opt.spectral = true;
        RenderResult r = render(*scene, *integrator, opt);
        EXPECT_EQ(r.nonfinite_samples, 0u) << name;
        EXPECT_GT(test::pixel_mean(r.image, 1).mean, 0.05) << name;
    }
}

} // namespace
} // namespace illum
