// pbrt-v4's plymesh makes its quads bilinear patches (and its triangles a triangle mesh) unless the mesh is
// displaced, when quads become two triangles (0 1 2, 0 2 3) first: the reader's keep_quads order (v0 v1 v3
// v2, a patch's p00 p10 p01 p11), the shapes built, and a hit on a non-planar quad at the patch's surface.
#include <gtest/gtest.h>

#include <cstring>

#include "illum/geometry/ply.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

// A non-planar quad (0, 0, 0) (1, 0, 0) (1, 1, 1) (0, 1, 0) and a triangle beside it, with uv.
const char* kPly = R"(ply
format ascii 1.0
element vertex 7
property float x
property float y
property float z
property float u
property float v
element face 2
property list uchar int vertex_indices
end_header
0 0 0 0 0
1 0 0 1 0
1 1 1 1 1
0 1 0 0 1
3 0 0 0 0
4 0 0 1 0
3 1 0 0 1
4 0 1 2 3
3 4 5 6
)";

TEST(PlyQuads, ReaderKeepsQuadsInPatchOrder) {
    TriangleMeshData d = parse_ply(kPly, std::strlen(kPly), "q.ply", true);
    EXPECT_EQ(d.quads, (std::vector<int>{0, 1, 3, 2}));
    EXPECT_EQ(d.indices, (std::vector<int>{4, 5, 6}));
    TriangleMeshData t = parse_ply(kPly, std::strlen(kPly), "q.ply");
    EXPECT_TRUE(t.quads.empty());
    EXPECT_EQ(t.indices, (std::vector<int>{0, 1, 2, 0, 2, 3, 4, 5, 6}));
}

TEST(PlyQuads, QuadsArePatchesUnlessDisplaced) {
    test::TempDir dir("plyquads");
    std::string path = dir.write("q.ply", kPly);
    auto text = [&](const std::string& extra) {
        return "LookAt 0.3 0.6 5  0.3 0.6 0  0 1 0\nCamera \"orthographic\"\nWorldBegin\n"
               "Texture \"d\" \"float\" \"constant\" \"float value\" 0\n"
               "Shape \"plymesh\" \"string filename\" \"" +
               path + "\" " + extra + "\n";
    };
    auto s = build_scene(parse_pbrt_string(text(""), "s.pbrt", "."));
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_EQ(s->accelerator.triangle_count(), 1u);
    EXPECT_EQ(s->accelerator.geometry_count(), 2u);
    // A ray down onto the quad at (x, y) = (0.3, 0.6) meets the saddle z = x y, with uv (x, y).
    SurfaceHit hit;
    ASSERT_TRUE(s->accelerator.intersect(Ray{{0.3f, 0.6f, 5}, {0, 0, -1}}, &hit));
    EXPECT_NEAR(hit.p.z, 0.3f * 0.6f, 1e-5f);
    EXPECT_NEAR(hit.uv.x, 0.3f, 1e-5f);
    EXPECT_NEAR(hit.uv.y, 0.6f, 1e-5f);
    // Displaced (by 0 here): all triangles, as pbrt-v4 converts the quads before refining.
    auto d = build_scene(
        parse_pbrt_string(text("\"texture displacement\" \"d\" \"float edgelength\" 10"), "s.pbrt", "."));
    EXPECT_EQ(d->accelerator.triangle_count(), 3u);
    EXPECT_EQ(d->accelerator.geometry_count(), 1u);
}

} // namespace
} // namespace illum
