// pbrt-v4's plymesh displacement: vertex normals of a symmetric mesh along its vertices; refinement until
// every edge is shorter than the bound in world space, the mesh staying watertight; each vertex moved by d(p,
// uv) along its normal (a constant d puts an icosahedron's vertices at radius 1 + d; a uv-dependent d moves
// each vertex by its own value); normals recomputed afterwards; through the scene: "edgelength", Option
// "displacementedgescale", the warnings gone, the errors, a render.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <map>

#include "illum/geometry/displace_mesh.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

// The unit icosahedron with spherical uv.
TriangleMesh icosahedron() {
    TriangleMesh m;
    float g = (1 + std::sqrt(5.0f)) / 2, s = 1 / std::sqrt(1 + g * g);
    m.p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
           {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (Point3f& q : m.p) {
        q = Point3f(Vector3f(q) * s);
        m.uv.push_back({0.5f + std::atan2(q.y, q.x) / (2 * kPi), std::acos(q.z) / kPi});
    }
    m.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    return m;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const TriangleMesh& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t f = 0; f < m.indices.size(); f += 3)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = m.indices[f + k], b = m.indices[f + (k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return uses;
}

class ConstantFloat final : public FloatTexture {
public:
    explicit ConstantFloat(float v) : v_(v) {}
    float evaluate(const TextureEvalContext&) const override { return v_; }

private:
    float v_;
};

class LinearInU final : public FloatTexture {
public:
    float evaluate(const TextureEvalContext& c) const override { return 0.2f * c.uv.x; }
};

TEST(DisplaceMesh, VertexNormalsOfASymmetricMesh) {
    TriangleMesh m = icosahedron();
    auto n = vertex_normals(m);
    // The icosahedron's faces wind outwards here ((v1 - v0) × (v2 - v1) points out); by symmetry the normal
    // at a vertex is along it.
    for (std::size_t i = 0; i < m.p.size(); ++i)
        EXPECT_GT(dot(Vector3f(n[i]), Vector3f(m.p[i])), 1 - 1e-5f) << i;
}

TEST(DisplaceMesh, RefinementBoundsEveryEdgeAndStaysWatertight) {
    for (float scale : {1.0f, 2.5f}) {
        TriangleMesh m = icosahedron();
        m.n = vertex_normals(m);
        Transform w = Transform::scale(scale, scale, scale);
        const float max_edge = 0.15f;
        refine_to_edge_length(m, w, max_edge, 1u << 22);
        EXPECT_GT(m.triangle_count(), 20u * 16);
        EXPECT_EQ(m.uv.size(), m.p.size());
        EXPECT_EQ(m.n.size(), m.p.size());
        for (std::size_t f = 0; f < m.triangle_count(); ++f) {
            auto v = m.vertices(f);
            for (int k = 0; k < 3; ++k)
                ASSERT_LT(distance(w(v[std::size_t(k)]), w(v[std::size_t((k + 1) % 3)])), max_edge) << f;
        }
        // Closed: every edge is shared by two triangles (a split edge's midpoint is shared by both sides).
        for (auto& [e, uses] : edge_uses(m)) ASSERT_EQ(uses, 2);
        // The refined surface is the icosahedron's: new vertices lie on its faces (inside the unit sphere).
        for (Point3f q : m.p) EXPECT_LE(length(Vector3f(q)), 1 + 1e-5f);
    }
    // A bound of 0 would never end: the caller must pass a positive one; too many triangles is an error.
    TriangleMesh m = icosahedron();
    EXPECT_THROW(refine_to_edge_length(m, Transform(), 1e-3f, 10000), Error);
}

TEST(DisplaceMesh, ConstantDisplacementMovesVerticesAlongTheirNormals) {
    const float d = 0.125f, max_edge = 0.3f;
    TriangleMesh refined = icosahedron();
    refined.n = vertex_normals(refined);
    refine_to_edge_length(refined, Transform(), max_edge, 1u << 22);
    TriangleMesh m = icosahedron();
    ConstantFloat tex(d);
    displace_mesh(m, tex, Transform(), max_edge);
    ASSERT_EQ(m.p.size(), refined.p.size());
    ASSERT_EQ(m.indices, refined.indices);
    for (std::size_t i = 0; i < m.p.size(); ++i) {
        Vector3f expected = Vector3f(refined.p[i]) + Vector3f(refined.n[i]) * d;
        EXPECT_LT(length(Vector3f(m.p[i]) - expected), 1e-6f) << i;
    }
    // The icosahedron's own vertices (normals along them) end at radius 1 + d. The normals are those of the
    // displaced triangles (recomputed, not carried), near the radial direction (the refinement's split order
    // is not symmetric about a vertex, so not along it exactly).
    auto recomputed = vertex_normals(m);
    for (std::size_t i = 0; i < m.p.size(); ++i) ASSERT_EQ(m.n[i], recomputed[i]);
    for (std::size_t i = 0; i < 12; ++i) {
        EXPECT_NEAR(length(Vector3f(m.p[i])), 1 + d, 1e-6f);
        EXPECT_GT(dot(Vector3f(m.n[i]), normalize(Vector3f(m.p[i]))), std::cos(5 * kPi / 180));
    }
    for (Normal3f n : m.n) EXPECT_NEAR(std::sqrt(dot(n, n)), 1, 1e-5f);
}

TEST(DisplaceMesh, TextureDisplacementUsesEachVertexsUv) {
    TriangleMesh refined = icosahedron();
    refined.n = vertex_normals(refined);
    refine_to_edge_length(refined, Transform(), 0.5f, 1u << 22);
    TriangleMesh m = icosahedron();
    LinearInU tex;
    displace_mesh(m, tex, Transform(), 0.5f);
    for (std::size_t i = 0; i < m.p.size(); ++i) {
        Vector3f expected = Vector3f(refined.p[i]) + Vector3f(refined.n[i]) * (0.2f * refined.uv[i].x);
        EXPECT_LT(length(Vector3f(m.p[i]) - expected), 1e-6f) << i;
    }
}

// An ASCII PLY of the icosahedron with uv.
std::string icosahedron_ply(bool with_uv) {
    TriangleMesh m = icosahedron();
    std::string s =
        fmt::format("ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\n"
                    "property float z\n{}element face {}\nproperty list uchar int vertex_indices\n"
                    "end_header\n",
                    m.p.size(), with_uv ? "property float u\nproperty float v\n" : "", m.triangle_count());
    for (std::size_t i = 0; i < m.p.size(); ++i) {
        s += fmt::format("{} {} {}", m.p[i].x, m.p[i].y, m.p[i].z);
        if (with_uv) s += fmt::format(" {} {}", m.uv[i].x, m.uv[i].y);
        s += "\n";
    }
    for (std::size_t f = 0; f < m.triangle_count(); ++f)
        s += fmt::format("3 {} {} {}\n", m.indices[3 * f], m.indices[3 * f + 1], m.indices[3 * f + 2]);
    return s;
}

TEST(DisplaceMeshScene, EdgeLengthOptionAndRender) {
    test::TempDir dir("displace");
    std::string with_uv = dir.write("ico.ply", icosahedron_ply(true)),
                without_uv = dir.write("ico-nouv.ply", icosahedron_ply(false));
    auto scene_text = [&](const std::string& options, const std::string& shape_params,
                          const std::string& ply = "") {
        return options + R"(LookAt 0 -4 0  0 0 0  0 0 1
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
WorldBegin
LightSource "distant" "point3 from" [1 -2 1] "point3 to" [0 0 0] "rgb L" [2 2 2]
Texture "bumps" "float" "constant" "float value" 0.2
Material "diffuse"
Shape "plymesh" "string filename" ")" +
               (ply.empty() ? with_uv : ply) + "\" " + shape_params + "\n";
    };
    auto build = [&](const std::string& text) { return build_scene(parse_pbrt_string(text, "s.pbrt", ".")); };
    auto plain = build(scene_text("", ""));
    EXPECT_EQ(plain->accelerator.triangle_count(), 20u);
    const std::string displace = "\"texture displacement\" \"bumps\" \"float edgelength\" 0.2";
    auto displaced = build(scene_text("", displace));
    EXPECT_TRUE(displaced->warnings.empty()) << displaced->warnings.front();
    std::size_t n1 = displaced->accelerator.triangle_count();
    EXPECT_GT(n1, 20u * 16);
    // Option "displacementedgescale" 0.5 halves the bound: about four times the triangles.
    auto finer = build(scene_text("Option \"displacementedgescale\" 0.5\n", displace));
    EXPECT_TRUE(finer->warnings.empty()) << finer->warnings.front();
    EXPECT_GT(finer->accelerator.triangle_count(), 3 * n1);
    // Renders: the displaced sphere (radius 1.2 at its vertices) covers more of the image.
    test::RenderSetup setup;
    setup.spp = 4;
    auto a = test::render_pbrt(scene_text("", ""), setup),
         b = test::render_pbrt(scene_text("", displace), setup);
    EXPECT_EQ(b.nonfinite_samples, 0u);
    EXPECT_GT(test::pixel_mean(b.image, 1).mean, 1.2 * test::pixel_mean(a.image, 1).mean);
    // Errors at the parameters: no uv; a non-positive edge length; a non-positive Option.
    test::expect_error([&] { build(scene_text("", "\"texture displacement\" \"bumps\"", without_uv)); },
                       "s.pbrt:8:", "needs the mesh's uv");
    test::expect_error(
        [&] { build(scene_text("", "\"texture displacement\" \"bumps\" \"float edgelength\" 0")); },
        "s.pbrt:8:", "must be positive");
    test::expect_error([&] { build(scene_text("Option \"displacementedgescale\" -1\n", "")); },
                       "s.pbrt:1:", "must be positive");
}

} // namespace
} // namespace illum
