// pbrt-v4's "ptex" texture in scenes: a Ptex file (written with tests/ptex_writer.h) whose faces are
// constant colours, on a triangle mesh and bilinear patches with "faceIndices" and a PLY file with
// "face_indices" (triangles and a quad): each face shows its own colour, decoded from 8 bits with the
// default gamma 2.2; a 1-channel file as "alpha" cuts holes face by face (the alpha test of triangles and of
// patches); files that cannot be read are errors naming them; the scene has no warnings.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <fstream>

#include "ptex_writer.h"
#include "test_support.h"

namespace illum {
namespace {

const double kColours[6][3] = {{200, 30, 30},  {30, 200, 30},  {30, 30, 200},
                               {200, 200, 30}, {30, 200, 200}, {200, 30, 200}};

std::string colour_file() {
    std::vector<test::TestFace> faces;
    for (const auto& c : kColours) faces.push_back(test::constant_face({c[0], c[1], c[2]}));
    return test::write_ptex("scene_colours.ptx", faces, 3, 0);
}

// Unit squares in three rows seen from above: y in [0.5, 1.5] a trianglemesh (faces 0, 1), y in
// [-0.5, 0.5] a bilinearmesh (faces 2, 3), y in [-1.5, -0.5] a PLY file: a quad (face 4) and two triangles
// (face 5). In each row the square at x in [-1, 0] has the first face.
std::string rows(const std::string& material) {
    std::string ply = ::testing::TempDir() + "scene_faces.ply";
    std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 3\nproperty list uchar int vertex_indices\n"
                          "property int face_indices\nend_header\n"
                          "-1 -1.5 0\n0 -1.5 0\n1 -1.5 0\n-1 -0.5 0\n0 -0.5 0\n1 -0.5 0\n"
                          "4 0 1 4 3 4\n3 1 2 5 5\n3 1 5 4 5\n";
    return fmt::format(R"(
{0}
Shape "trianglemesh" "point3 P" [-1 0.5 0  0 0.5 0  1 0.5 0  -1 1.5 0  0 1.5 0  1 1.5 0]
    "integer indices" [0 1 4  0 4 3  1 2 5  1 5 4] "integer faceIndices" [0 0 1 1] {1}
Shape "bilinearmesh" "point3 P" [-1 -0.5 0  0 -0.5 0  1 -0.5 0  -1 0.5 0  0 0.5 0  1 0.5 0]
    "integer indices" [0 1 3 4  1 2 4 5] "integer faceIndices" [2 3] {1}
Shape "plymesh" "string filename" "{2}" {1}
)",
                       material, material.empty() ? "\"texture alpha\" \"holes\"" : "", ply);
}

const char* kView = R"(
LookAt 0 0 5  0 0 0  0 1 0
Camera "orthographic" "float screenwindow" [-1 1 -1.5 1.5]
Film "rgb" "integer xresolution" [8] "integer yresolution" [12]
PixelFilter "box" "float xradius" [0.5] "float yradius" [0.5]
WorldBegin
)";

// The 2 x 2 pixels inside the square of face f (8 x 12 pixels over [-1, 1] x [-1.5, 1.5]; the image's
// x runs along world -x, as pbrt-v4's LookAt makes it).
template <class F>
void for_face_pixels(int f, F&& visit) {
    int row = f / 2, col0 = f % 2 == 0 ? 5 : 1;
    for (int y = 4 * row + 1; y <= 4 * row + 2; ++y)
        for (int x = col0; x <= col0 + 1; ++x) visit(x, y);
}

TEST(PtexScene, EachFaceShowsItsColour) {
    std::string file = colour_file();
    std::string text =
        std::string(kView) +
        fmt::format("Texture \"faces\" \"spectrum\" \"ptex\" \"string filename\" \"{}\"\n", file) +
        rows("Material \"diffuse\" \"texture reflectance\" \"faces\"");
    auto scene = build_scene(parse_pbrt_string(text, "<test>", "."));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    test::RenderSetup s;
    s.integrator = "albedo";
    s.spp = 4;
    auto r = test::render_pbrt(text, s);
    for (int f = 0; f < 6; ++f)
        for_face_pixels(f, [&](int x, int y) {
            Color3 c = r.image(x, y);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(c[k], std::pow(kColours[f][k] / 255, 2.2), 1e-5)
                    << "face " << f << " pixel " << x << " " << y << " channel " << k;
        });
}

// scenes/ptex (compared with pbrt-v4 in docs/verification.md) builds without warnings and filters.
TEST(PtexScene, TheComparisonSceneBuildsWithoutWarnings) {
    const std::string dir = std::string(ILLUM_SOURCE_DIR) + "/scenes/ptex";
    auto scene = build_scene(parse_pbrt_file(dir + "/ptex.pbrt"));
    EXPECT_TRUE(scene->warnings.empty()) << scene->warnings.front();
    EXPECT_TRUE(scene->texture_filtering);
}

TEST(PtexScene, AlphaCutsFaceByFace) {
    // Faces 0, 3 and 5 opaque (alpha 1), the others holes, over an emitter of radiance 1.
    std::vector<test::TestFace> faces;
    for (int f = 0; f < 6; ++f)
        faces.push_back(test::constant_face({f == 0 || f == 3 || f == 5 ? 255.0 : 0.0}));
    std::string file = test::write_ptex("scene_alpha.ptx", faces, 1, 0);
    std::string text = std::string(kView) + R"(
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [1 1 1]
  Material "diffuse" "rgb reflectance" [0 0 0]
  Translate 0 0 -1
  Shape "trianglemesh" "point3 P" [-2 -2 0 2 -2 0 2 2 0 -2 2 0] "integer indices" [0 1 2 0 2 3]
AttributeEnd
Material "diffuse" "rgb reflectance" [0 0 0]
)" +
                       fmt::format("Texture \"holes\" \"float\" \"ptex\" \"string filename\" \"{}\" \"string "
                                   "encoding\" \"linear\"\n",
                                   file) +
                       rows("");
    test::RenderSetup s;
    s.spp = 4;
    auto r = test::render_pbrt(text, s);
    for (int f = 0; f < 6; ++f) {
        double expected = f == 0 || f == 3 || f == 5 ? 0 : 1;
        for_face_pixels(f,
                        [&](int x, int y) { EXPECT_NEAR(r.image(x, y).g, expected, 1e-5) << "face " << f; });
    }
}

TEST(PtexScene, UnreadableFilesAreErrorsNamingThem) {
    std::string bad = ::testing::TempDir() + "not_ptex.ptx";
    std::ofstream(bad) << "this is not a Ptex file";
    std::string two_channels = test::write_ptex("two_channels.ptx", {test::constant_face({1, 2})}, 2, 0);
    for (const std::string& file : {bad, ::testing::TempDir() + "no_such_file.ptx", two_channels}) {
        std::string text =
            std::string(kView) +
            fmt::format("Texture \"t\" \"spectrum\" \"ptex\" \"string filename\" \"{}\"\n", file) +
            "Material \"diffuse\" \"texture reflectance\" \"t\"\n"
            "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0]\n";
        try {
            build_scene(parse_pbrt_string(text, "<test>", "."));
            ADD_FAILURE() << "no error for " << file;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
        }
    }
}

TEST(PtexScene, FaceIndicesMustMatchTheFaces) {
    std::string text = std::string(kView) +
                       "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n"
                       "    \"integer faceIndices\" [0 1]\n";
    try {
        build_scene(parse_pbrt_string(text, "<test>", "."));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("2 \"faceIndices\" for 1 faces"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("<test>:"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace illum
