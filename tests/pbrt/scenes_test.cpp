// Every scene under ILLUM_SHARED_DIR/scenes parses, with the counts and values the files give.
#include <gtest/gtest.h>

#include <filesystem>

#include "illum/geometry/ply.h"
#include "illum/scene/pbrt/parser.h"
#include "test_util.h"

namespace illum {
namespace {

namespace fs = std::filesystem;

std::string scene(const std::string& rel) { return (fs::path(ILLUM_SHARED_DIR) / "scenes" / rel).string(); }

#define REQUIRE_SCENE(path)                                                                                  \
    if (!test::shared_dir_exists()) GTEST_SKIP() << "shared dir absent";                                     \
    if (!fs::exists(path)) GTEST_SKIP() << path << " absent"

int count_named(const SceneDesc& s) { return int(s.named_materials.size()); }

TEST(PbrtScenes, AllSharedScenesParse) {
    if (!test::shared_dir_exists()) GTEST_SKIP() << "shared dir absent";
    int n = 0;
    for (auto& e : fs::recursive_directory_iterator(fs::path(ILLUM_SHARED_DIR) / "scenes")) {
        std::string name = e.path().filename().string();
        if (name != "scene-v4.pbrt" && name != "scene.pbrt" && name != "test.pbrt") continue;
        SCOPED_TRACE(e.path().string());
        SceneDesc s = parse_pbrt_file(e.path().string());
        ++n;
        EXPECT_EQ(s.camera.type, "perspective");
        EXPECT_FALSE(s.shapes.empty());
        EXPECT_GE(s.area_lights.size(), 1u);
        // Participating media are issue 11's: until then a scene with media gets exactly that warning.
        for (const std::string& w : s.warnings)
            EXPECT_TRUE(!s.media.empty() &&
                        w.find("participating media are not supported") != std::string::npos)
                << w;
        for (auto& sh : s.shapes) {
            if (!sh.material.name.empty()) {
                EXPECT_TRUE(s.named_materials.count(sh.material.name));
            }
            if (sh.material.index >= 0) {
                EXPECT_LT(size_t(sh.material.index), s.materials.size());
            }
            if (sh.area_light >= 0) {
                EXPECT_LT(size_t(sh.area_light), s.area_lights.size());
            }
            if (sh.type == "plymesh") {
                EXPECT_TRUE(fs::exists(sh.params.get_string("filename", "")));
            }
        }
    }
    EXPECT_GE(n, 8);
}

TEST(PbrtScenes, CornellBox) {
    std::string path = scene("cornell-box/scene-v4.pbrt");
    REQUIRE_SCENE(path);
    SceneDesc s = parse_pbrt_file(path);
    EXPECT_EQ(s.filename, path);
    EXPECT_EQ(s.base_dir, scene("cornell-box"));
    ASSERT_EQ(s.shapes.size(), 8u);
    for (auto& sh : s.shapes) EXPECT_EQ(sh.type, "trianglemesh");
    EXPECT_EQ(s.materials.size(), 8u);
    EXPECT_EQ(count_named(s), 8);
    EXPECT_TRUE(s.lights.empty());
    ASSERT_EQ(s.area_lights.size(), 1u);
    int emitters = 0;
    for (auto& sh : s.shapes) {
        if (sh.area_light < 0) continue;
        ++emitters;
        EXPECT_EQ(sh.material.name, "Light");
        auto L = s.area_lights[sh.area_light].params.get_rgb("L");
        ASSERT_TRUE(L);
        EXPECT_EQ(L->r, 17.0f);
        EXPECT_EQ(L->g, 12.0f);
        EXPECT_EQ(L->b, 4.0f);
        EXPECT_EQ(sh.params.get_point3s("P").size(), 4u);
        EXPECT_EQ(sh.params.get_normals("N").size(), 4u);
    }
    EXPECT_EQ(emitters, 1);
    EXPECT_EQ(s.shapes[0].material.name, "Floor");
    EXPECT_EQ(s.shapes[0].params.get_ints("indices"), (std::vector<int>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(s.camera.type, "perspective");
    EXPECT_FLOAT_EQ(s.camera.params.get_float("fov", 0), 19.5f);
    EXPECT_EQ(s.film.params.get_int("xresolution", 0), 1024);
    EXPECT_EQ(s.film.params.get_int("yresolution", 0), 1024);
    EXPECT_EQ(s.integrator.type, "path");
    EXPECT_EQ(s.integrator.params.get_int("maxdepth", 0), 65);
    EXPECT_EQ(s.sampler.type, "sobol");
    EXPECT_EQ(s.filter.type, "triangle");
    // Transform [ 1 -0 -0 -0 -0 1 -0 -0 -0 -0 -1 -0 -0 -1 6.8 1 ] is given column by column.
    const double expected[4][4] = {{1, 0, 0, 0}, {0, 1, 0, -1}, {0, 0, -1, 6.8}, {0, 0, 0, 1}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_DOUBLE_EQ(s.camera.camera_from_world.matrix()(r, c), expected[r][c]);
    // The camera sits at (0, 1, 6.8) looking down -z.
    Point3f eye = s.camera.camera_from_world.inverse()(Point3f(0, 0, 0));
    EXPECT_NEAR(eye.x, 0, 1e-6);
    EXPECT_NEAR(eye.y, 1, 1e-6);
    EXPECT_NEAR(eye.z, 6.8, 1e-5);
    for (auto& sh : s.shapes) EXPECT_TRUE(sh.world_from_object.is_identity());
}

TEST(PbrtScenes, CornellBoxMeasured) {
    std::string path = scene("cornell-box-measured/scene.pbrt");
    REQUIRE_SCENE(path);
    SceneDesc s = parse_pbrt_file(path);
    EXPECT_EQ(s.shapes.size(), 8u);
    EXPECT_EQ(s.materials.size(), 4u);
    EXPECT_EQ(count_named(s), 0);
    ASSERT_EQ(s.area_lights.size(), 1u);
    EXPECT_EQ(s.shapes.back().area_light, 0);
    EXPECT_EQ(s.shapes.back().material.index, 3);
    EXPECT_EQ(s.shapes[0].area_light, -1);
    EXPECT_FLOAT_EQ(s.camera.params.get_float("fov", 0), 39.3077f);
    EXPECT_EQ(s.film.params.get_string("filename", ""), "cornell-box.exr");
    // Scale -1 1 1 then LookAt: the eye is at (278, 273, -800) and the image is mirrored.
    const Transform& cfw = s.camera.camera_from_world;
    Point3f eye = cfw.inverse()(Point3f(0, 0, 0));
    EXPECT_NEAR(eye.x, 278, 1e-3);
    EXPECT_NEAR(eye.y, 273, 1e-3);
    EXPECT_NEAR(eye.z, -800, 1e-3);
    EXPECT_TRUE(cfw.swaps_handedness());
    Point3f p = cfw(Point3f(279, 273, -800));
    EXPECT_NEAR(p.x, -1, 1e-4);
}

TEST(PbrtScenes, VeachMis) {
    std::string path = scene("veach-mis/scene-v4.pbrt");
    REQUIRE_SCENE(path);
    SceneDesc s = parse_pbrt_file(path);
    EXPECT_EQ(s.shapes.size(), 9u);
    EXPECT_EQ(count_named(s), 6);
    EXPECT_EQ(s.area_lights.size(), 3u);
    int spheres = 0;
    for (auto& sh : s.shapes) {
        if (sh.type != "sphere") continue;
        ++spheres;
        EXPECT_GE(sh.area_light, 0);
        EXPECT_EQ(sh.material.name, "Null");
        Point3f c = sh.world_from_object(Point3f(0, 0, 0));
        EXPECT_NEAR(c.x, 0, 1e-6);
        EXPECT_NEAR(c.y, 6.5, 1e-6);
    }
    EXPECT_EQ(spheres, 3);
    EXPECT_EQ(s.sampler.params.get_int("pixelsamples", 0), 1); // followed by a comment in the file
    EXPECT_EQ(s.film.params.get_int("xresolution", 0), 1280);
    auto k = s.materials[s.named_materials.at("Smooth")].params.get_rgb("k");
    ASSERT_TRUE(k);
    EXPECT_FLOAT_EQ(k->r, 3.912949f);
}

TEST(PbrtScenes, CoffeeWithMeshes) {
    std::string path = scene("coffee/scene-v4.pbrt");
    REQUIRE_SCENE(path);
    SceneDesc s = parse_pbrt_file(path);
    EXPECT_EQ(s.shapes.size(), 23u);
    EXPECT_EQ(count_named(s), 5);
    EXPECT_EQ(s.materials.size(), 8u); // 5 named + 3 anonymous
    EXPECT_EQ(s.area_lights.size(), 3u);
    const MaterialDesc& metal = s.materials[s.named_materials.at("Metal")];
    EXPECT_EQ(metal.type, "conductor");
    EXPECT_EQ(metal.params.find("eta")->strings, (std::vector<std::string>{"metal-Ag-eta"}));
    EXPECT_FALSE(s.materials[s.named_materials.at("Glass")].params.get_bool("remaproughness", true));
    int plys = 0;
    for (auto& sh : s.shapes) {
        if (sh.type != "plymesh") continue;
        ++plys;
        std::string file = sh.params.get_string("filename", "");
        EXPECT_EQ(fs::path(file).parent_path(), fs::path(scene("coffee/models")));
        TriangleMeshData m = read_ply(file);
        EXPECT_GT(m.indices.size(), 0u);
    }
    EXPECT_EQ(plys, 20);
}

} // namespace
} // namespace illum
