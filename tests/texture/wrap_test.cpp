// Texel addressing outside the image (texture/mipmap.h, wrap_texel): pbrt-v4's four wrap modes, the
// octahedral sphere's mirrored neighbours worked out by hand from its rules.
#include <gtest/gtest.h>

#include <utility>

#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/texture/mipmap.h"

namespace illum {
namespace {

std::pair<int, int> wrapped(WrapMode m, int x, int y, bool* inside = nullptr) {
    bool in = wrap_texel(m, 4, 4, &x, &y);
    if (inside) *inside = in;
    return {x, y};
}

TEST(WrapTexel, RepeatClampBlack) {
    EXPECT_EQ(wrapped(WrapMode::Repeat, -1, 5), std::make_pair(3, 1));
    EXPECT_EQ(wrapped(WrapMode::Clamp, -1, 5), std::make_pair(0, 3));
    bool inside = true;
    wrapped(WrapMode::Black, -1, 2, &inside);
    EXPECT_FALSE(inside);
    EXPECT_EQ(wrapped(WrapMode::Black, 2, 3, &inside), std::make_pair(2, 3));
    EXPECT_TRUE(inside);
}

TEST(WrapTexel, OctahedralSphereMirrorsAcrossTheEdgeAndTheMiddle) {
    // 4×4: past the left edge x → -x, y → 3 - y; past the right x → 7 - x, y → 3 - y; past the top
    // x → 3 - x, y → -y; past the bottom x → 3 - x, y → 7 - y; a corner takes both in that order.
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, -1, 0), std::make_pair(1, 3));
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, 4, 1), std::make_pair(3, 2));
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, 1, -1), std::make_pair(2, 1));
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, 2, 4), std::make_pair(1, 3));
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, -1, -1), std::make_pair(2, 3));
    EXPECT_EQ(wrapped(WrapMode::OctahedralSphere, 2, 2), std::make_pair(2, 2));
}

TEST(WrapTexel, OctahedralSphereImageTexturesBuildWithoutWarnings) {
    const std::string dir = std::string(ILLUM_SOURCE_DIR) + "/scenes/texture-filtering";
    auto scene = build_scene(parse_pbrt_string(R"(Camera "perspective"
WorldBegin
Texture "t" "spectrum" "imagemap" "string filename" "checker.png" "string wrap" "octahedralsphere"
Material "diffuse" "texture reflectance" "t"
Shape "sphere"
)",
                                               "<test>", dir));
    EXPECT_TRUE(scene->warnings.empty()) << (scene->warnings.empty() ? "" : scene->warnings[0]);
}

} // namespace
} // namespace illum
