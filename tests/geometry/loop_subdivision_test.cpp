// pbrt-v4's loopsubdiv (Loop subdivision pushed to the limit surface): face and vertex counts and
// watertightness at every level; limit positions against the closed forms of the masks (a regular
// tetrahedron's vertex goes to v/5, an icosahedron's to (5 + √5)/10 v, a lone triangle's corner to
// 3/5 a + 1/5 (b + c) by the boundary rule); the limit point of a vertex does not move when the mesh is
// subdivided further (the masks' eigenvector property, interior and boundary); limit normals by symmetry;
// the shape through the scene builder without warnings, and a render.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "illum/geometry/loop_subdivision.h"
#include "pbrt/test_util.h"
#include "test_support.h"

namespace illum {
namespace {

// A regular tetrahedron centred at the origin, faces wound counter-clockwise seen from outside.
const std::vector<Point3f> kTetP = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
const std::vector<int> kTetI = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};

// The unit icosahedron.
void icosahedron(std::vector<Point3f>* p, std::vector<int>* idx) {
    float g = (1 + std::sqrt(5.0f)) / 2, s = 1 / std::sqrt(1 + g * g);
    *p = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
          {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (Point3f& q : *p) q = Point3f(Vector3f(q) * s);
    *idx = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
            4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
            6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
}

// How many faces use each undirected edge.
std::map<std::pair<int, int>, int> edge_uses(const std::vector<std::uint32_t>& idx) {
    std::map<std::pair<int, int>, int> uses;
    for (std::size_t f = 0; f < idx.size(); f += 3)
        for (int k = 0; k < 3; ++k) {
            int a = int(idx[f + k]), b = int(idx[f + (k + 1) % 3]);
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return uses;
}

TEST(LoopSubdivision, CountsAndWatertightness) {
    for (int levels = 0; levels <= 4; ++levels) {
        SubdividedMesh m = loop_subdivide(kTetP, kTetI, levels);
        std::size_t faces = 4u << (2 * levels); // F · 4^levels
        ASSERT_EQ(m.indices.size(), 3 * faces);
        // Closed: every edge in exactly two faces, and Euler's V - E + F = 2.
        auto uses = edge_uses(m.indices);
        for (auto& [e, n] : uses) ASSERT_EQ(n, 2) << e.first << " " << e.second;
        EXPECT_EQ(uses.size(), faces * 3 / 2);
        EXPECT_EQ(long(m.p.size()) - long(uses.size()) + long(faces), 2);
        EXPECT_EQ(m.n.size(), m.p.size());
    }
}

TEST(LoopSubdivision, RegularTetrahedronLimitPositions) {
    // Valence 3: γ = 1/(3 + 3/(8 · 3/16)) = 1/5, so the limit is 2/5 v + 1/5 Σ others = v/5 (Σ others = -v),
    // at every level (a vertex's limit point does not move).
    for (int levels : {0, 1, 3}) {
        SubdividedMesh m = loop_subdivide(kTetP, kTetI, levels);
        for (int v = 0; v < 4; ++v) {
            Vector3f d = m.p[std::size_t(v)] - Point3f(Vector3f(kTetP[std::size_t(v)]) * 0.2f);
            EXPECT_LT(length(d), 1e-5f) << "levels " << levels << " vertex " << v;
            // By symmetry the limit normal is along v: pbrt-v4's tangents S × T point against the winding's
            // normal, here inwards.
            Vector3f n = normalize(Vector3f(m.n[std::size_t(v)]));
            EXPECT_LT(dot(n, normalize(Vector3f(kTetP[std::size_t(v)]))), -1 + 1e-5f);
        }
    }
}

TEST(LoopSubdivision, IcosahedronLimitPositions) {
    std::vector<Point3f> p;
    std::vector<int> idx;
    icosahedron(&p, &idx);
    // Valence 5: β = 3/40, γ = 1/10; the five neighbours sum to √5 v (unit vertices at cos 1/√5):
    // limit = (1/2 + √5/10) v.
    double k = 0.5 + std::sqrt(5.0) / 10;
    for (int levels : {0, 2}) {
        SubdividedMesh m = loop_subdivide(p, idx, levels);
        EXPECT_EQ(m.indices.size(), 3u * 20 * (1u << (2 * levels)));
        for (int v = 0; v < 12; ++v) {
            EXPECT_NEAR(m.p[std::size_t(v)].x, k * p[std::size_t(v)].x, 1e-5);
            EXPECT_NEAR(m.p[std::size_t(v)].y, k * p[std::size_t(v)].y, 1e-5);
            EXPECT_NEAR(m.p[std::size_t(v)].z, k * p[std::size_t(v)].z, 1e-5);
            Vector3f n = normalize(Vector3f(m.n[std::size_t(v)]));
            EXPECT_LT(dot(n, Vector3f(p[std::size_t(v)])), -1 + 1e-5f);
        }
        // The limit surface lies inside the control mesh's convex hull (the masks' weights are positive).
        for (Point3f q : m.p) EXPECT_LT(length(Vector3f(q)), 1.0f);
    }
}

// The limit of every interior vertex of the mesh at level L equals its limit at level L + 1 (even vertices
// keep their numbers): Loop's subdivision and limit masks agree. On the boundary they do not: pbrt-v4's limit
// mask there is (1/5, 3/5, 1/5), not the cubic B-spline's (1/6, 2/3, 1/6), so a boundary limit point moves a
// little with each level (BoundaryRule checks pbrt-v4's mask itself).
void expect_limit_invariance(const std::vector<Point3f>& p, const std::vector<int>& idx) {
    for (int levels = 0; levels < 3; ++levels) {
        SubdividedMesh a = loop_subdivide(p, idx, levels), b = loop_subdivide(p, idx, levels + 1);
        std::vector<bool> boundary(a.p.size(), false);
        for (auto& [e, n] : edge_uses(a.indices))
            if (n == 1) boundary[std::size_t(e.first)] = boundary[std::size_t(e.second)] = true;
        for (std::size_t v = 0; v < a.p.size(); ++v) {
            if (boundary[v]) continue;
            EXPECT_LT(length(a.p[v] - b.p[v]), 1e-5f) << "levels " << levels << " vertex " << v;
            Vector3f na = normalize(Vector3f(a.n[v])), nb = normalize(Vector3f(b.n[v]));
            EXPECT_GT(dot(na, nb), 1 - 1e-4f) << "levels " << levels << " vertex " << v;
        }
    }
}

TEST(LoopSubdivision, LimitPointsDoNotMoveUnderFurtherSubdivision) {
    std::vector<Point3f> p;
    std::vector<int> idx;
    icosahedron(&p, &idx);
    // A bumpy icosahedron: irregular geometry, valences 5 and 6 after the first level.
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = Point3f(Vector3f(p[i]) * (1 + 0.3f * float(i % 3)));
    expect_limit_invariance(p, idx);
    // An open, non-planar patch: a 3 × 3 grid of quads split into triangles, heights varying.
    std::vector<Point3f> g;
    std::vector<int> gi;
    for (int j = 0; j <= 3; ++j)
        for (int i = 0; i <= 3; ++i) g.push_back({float(i), float(j), 0.3f * float((i * 7 + j * 3) % 4)});
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            int a = j * 4 + i, b = a + 1, c = a + 4, d = c + 1;
            gi.insert(gi.end(), {a, b, d, a, d, c});
        }
    expect_limit_invariance(g, gi);
}

TEST(LoopSubdivision, BoundaryRule) {
    // A lone triangle is all boundary: pbrt-v4's limit of a corner is 3/5 a + 1/5 (b + c) at level 0 (and,
    // the boundary rules keeping a corner's neighbours on its two edges, at every level: 3/4 a + 1/8 (b + c)
    // and the midpoints (a + b)/2, (a + c)/2 have the same 3/5, 1/5 combination only at level 0, so the
    // check is at level 0); the surface stays in its plane, with normals along its normal.
    std::vector<Point3f> p = {{0, 0, 0}, {4, 0, 0}, {1, 3, 0}};
    std::vector<int> idx = {0, 1, 2};
    for (int levels : {0, 1, 3}) {
        SubdividedMesh m = loop_subdivide(p, idx, levels);
        for (int v = 0; v < 3 && levels == 0; ++v) {
            Vector3f expected =
                Vector3f(p[std::size_t(v)]) * 0.6f +
                (Vector3f(p[std::size_t((v + 1) % 3)]) + Vector3f(p[std::size_t((v + 2) % 3)])) * 0.2f;
            EXPECT_LT(length(Vector3f(m.p[std::size_t(v)]) - expected), 1e-5f) << levels << " " << v;
        }
        for (std::size_t v = 0; v < m.p.size(); ++v) {
            EXPECT_EQ(m.p[v].z, 0);
            Vector3f n = normalize(Vector3f(m.n[v]));
            EXPECT_NEAR(std::abs(n.z), 1, 1e-5f) << levels << " " << v;
        }
    }
    // An open mesh, two triangles of the unit square: the boundary stays a boundary (each of the 4 sides
    // split into 8 edges used by one face), within the square (the corners are rounded off: a corner is
    // smoothed by the boundary rule as any boundary vertex, pbrt-v4 has no creases).
    SubdividedMesh sq = loop_subdivide({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3}, 3);
    EXPECT_EQ(sq.indices.size(), 3u * 2 * 64);
    for (Point3f q : sq.p) {
        EXPECT_GE(q.x, -1e-6f);
        EXPECT_LE(q.x, 1 + 1e-6f);
        EXPECT_GE(q.y, -1e-6f);
        EXPECT_LE(q.y, 1 + 1e-6f);
    }
    // Level 0's corner (0, 0) goes to 1/5 ((1, 0) + (0, 1)).
    EXPECT_NEAR(loop_subdivide({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 0, 2, 3}, 0).p[0].x,
                0.2f, 1e-6f);
    int boundary_edges = 0;
    for (auto& [e, n] : edge_uses(sq.indices)) boundary_edges += n == 1;
    EXPECT_EQ(boundary_edges, 4 * 8);
}

TEST(LoopSubdivisionScene, BuildsWithoutWarningsAndRenders) {
    std::string scene = R"(LookAt 0 -1.2 0  0 0 0  0 0 1
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 16 "integer yresolution" 16
WorldBegin
LightSource "distant" "point3 from" [1 -2 1] "point3 to" [0 0 0] "rgb L" [2 2 2]
Material "diffuse"
Shape "loopsubdiv" "integer levels" 2 "string scheme" "loop"
  "point3 P" [1 1 1  1 -1 -1  -1 1 -1  -1 -1 1] "integer indices" [0 1 2 0 3 1 0 2 3 1 3 2]
)";
    auto s = build_scene(parse_pbrt_string(scene, "<test>", "."));
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_EQ(s->accelerator.triangle_count(), 4u * 16);
    test::RenderSetup setup;
    setup.spp = 4;
    auto r = test::render_pbrt(scene, setup);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    auto m = test::pixel_mean(r.image, 1);
    EXPECT_GT(m.mean, 0.01);
    test::expect_error(
        [] {
            build_scene(parse_pbrt_string(
                "WorldBegin\nShape \"loopsubdiv\" \"point3 P\" [0 0 0 1 0 0 0 1 0]\n", "<test>", "."));
        },
        "<test>:2:", "loopsubdiv needs");
}

} // namespace
} // namespace illum
