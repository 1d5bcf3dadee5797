#include "illum/geometry/loop_subdivision.h"

#include <array>
#include <cmath>
#include <unordered_map>

namespace illum {

namespace {

using Face = std::array<int, 3>;

// A triangle mesh with each face's neighbour across edge k = (v[k], v[k+1]) (-1 on a boundary), and for each
// vertex one face that holds it.
struct Topology {
    std::vector<Face> faces;
    std::vector<std::array<int, 3>> across;
    std::vector<int> vertex_face;

    Topology(std::vector<Face> f, std::size_t vertex_count) : faces(std::move(f)) {
        across.assign(faces.size(), {-1, -1, -1});
        vertex_face.assign(vertex_count, -1);
        // Undirected edge -> the first face and edge number that had it.
        std::unordered_map<std::uint64_t, std::pair<int, int>> first;
        first.reserve(faces.size() * 2);
        for (int fi = 0; fi < int(faces.size()); ++fi)
            for (int k = 0; k < 3; ++k) {
                vertex_face[std::size_t(faces[fi][k])] = fi;
                auto [it, fresh] = first.try_emplace(edge_key(faces[fi][k], faces[fi][(k + 1) % 3]), fi, k);
                if (fresh) continue;
                auto [g, j] = it->second;
                if (g >= 0) {
                    across[std::size_t(g)][std::size_t(j)] = fi;
                    across[std::size_t(fi)][std::size_t(k)] = g;
                    it->second = {-1, -1}; // a third face on the edge stays unlinked (non-manifold)
                }
            }
    }

    static std::uint64_t edge_key(int a, int b) {
        if (a > b) std::swap(a, b);
        return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    }
    int corner(int f, int v) const {
        const Face& x = faces[std::size_t(f)];
        return x[0] == v ? 0 : (x[1] == v ? 1 : 2);
    }
    // The face after f around v: across the edge from v to the vertex after it.
    int next_face(int f, int v) const { return across[std::size_t(f)][std::size_t(corner(f, v))]; }
    // The face before f around v: across the edge from the vertex before v to v.
    int prev_face(int f, int v) const { return across[std::size_t(f)][std::size_t((corner(f, v) + 2) % 3)]; }
    int next_vertex(int f, int v) const { return faces[std::size_t(f)][std::size_t((corner(f, v) + 1) % 3)]; }
    int prev_vertex(int f, int v) const { return faces[std::size_t(f)][std::size_t((corner(f, v) + 2) % 3)]; }

    // v's neighbours in pbrt-v4's order, and whether v is on a boundary. Interior: the vertex after v in
    // each face, walking to the next face. Boundary: from the last face reachable that way, the vertex after
    // v, then the vertex before v in each face walking back to the first face.
    bool ring(int v, std::vector<int>* out) const {
        out->clear();
        int start = vertex_face[std::size_t(v)];
        if (start < 0) return false;
        const std::size_t limit = faces.size() + 1; // a non-manifold fan cannot loop for ever
        int f = start;
        std::size_t steps = 0;
        do {
            out->push_back(next_vertex(f, v));
            f = next_face(f, v);
        } while (f >= 0 && f != start && ++steps < limit);
        if (f == start) return false;
        // A boundary vertex: walk to the end of the fan, then back.
        out->clear();
        f = start;
        steps = 0;
        for (int g; (g = next_face(f, v)) >= 0 && steps < limit; ++steps) f = g;
        out->push_back(next_vertex(f, v));
        steps = 0;
        do {
            out->push_back(prev_vertex(f, v));
            f = prev_face(f, v);
        } while (f >= 0 && ++steps < limit);
        return true;
    }
};

float loop_beta(int n) { return n == 3 ? 3.0f / 16.0f : 3.0f / (8.0f * float(n)); }

// (1 - n w) v + w Σ ring.
Point3f one_ring_weighted(Point3f v, const std::vector<int>& ring, const std::vector<Point3f>& p, float w) {
    Vector3f sum = Vector3f(v) * (1 - float(ring.size()) * w);
    for (int r : ring) sum += Vector3f(p[std::size_t(r)]) * w;
    return Point3f(sum);
}

// (1 - 2 w) v + w (r_first + r_last).
Point3f boundary_weighted(Point3f v, const std::vector<int>& ring, const std::vector<Point3f>& p, float w) {
    return Point3f(Vector3f(v) * (1 - 2 * w) +
                   (Vector3f(p[std::size_t(ring.front())]) + Vector3f(p[std::size_t(ring.back())])) * w);
}

} // namespace

SubdividedMesh loop_subdivide(const std::vector<Point3f>& points, const std::vector<int>& indices,
                              int levels) {
    std::vector<Point3f> p = points;
    std::vector<Face> faces(indices.size() / 3);
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i] = {indices[3 * i], indices[3 * i + 1], indices[3 * i + 2]};
    std::vector<int> ring;
    for (int level = 0; level < levels; ++level) {
        Topology t(std::move(faces), p.size());
        std::vector<Point3f> next(p.size());
        // Even vertices.
        for (int v = 0; v < int(p.size()); ++v) {
            bool boundary = t.ring(v, &ring);
            if (ring.empty())
                next[std::size_t(v)] = p[std::size_t(v)]; // in no face: unchanged
            else if (boundary)
                next[std::size_t(v)] = boundary_weighted(p[std::size_t(v)], ring, p, 1.0f / 8);
            else
                next[std::size_t(v)] =
                    one_ring_weighted(p[std::size_t(v)], ring, p, loop_beta(int(ring.size())));
        }
        // Odd vertices, one per edge, numbered after the even ones.
        std::vector<std::array<int, 3>> edge_vertex(t.faces.size());
        for (int f = 0; f < int(t.faces.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                int g = t.across[std::size_t(f)][std::size_t(k)];
                if (g >= 0 && g < f) { // made by the neighbour already
                    int a = t.faces[std::size_t(f)][std::size_t(k)],
                        b = t.faces[std::size_t(f)][std::size_t((k + 1) % 3)];
                    for (int j = 0; j < 3; ++j) {
                        int c = t.faces[std::size_t(g)][std::size_t(j)],
                            d = t.faces[std::size_t(g)][std::size_t((j + 1) % 3)];
                        if ((c == a && d == b) || (c == b && d == a))
                            edge_vertex[std::size_t(f)][std::size_t(k)] =
                                edge_vertex[std::size_t(g)][std::size_t(j)];
                    }
                    continue;
                }
                const Face& x = t.faces[std::size_t(f)];
                Vector3f a(p[std::size_t(x[std::size_t(k)])]), b(p[std::size_t(x[std::size_t((k + 1) % 3)])]);
                Vector3f q;
                if (g < 0) {
                    q = (a + b) * 0.5f;
                } else {
                    Vector3f c(p[std::size_t(x[std::size_t((k + 2) % 3)])]);
                    const Face& y = t.faces[std::size_t(g)];
                    int other = y[0];
                    for (int j : y)
                        if (j != x[std::size_t(k)] && j != x[std::size_t((k + 1) % 3)]) other = j;
                    Vector3f d(p[std::size_t(other)]);
                    q = (a + b) * (3.0f / 8) + (c + d) * (1.0f / 8);
                }
                edge_vertex[std::size_t(f)][std::size_t(k)] = int(next.size());
                next.push_back(Point3f(q));
            }
        std::vector<Face> children;
        children.reserve(4 * t.faces.size());
        for (std::size_t f = 0; f < t.faces.size(); ++f) {
            const Face& x = t.faces[f];
            int ab = edge_vertex[f][0], bc = edge_vertex[f][1], ca = edge_vertex[f][2];
            children.push_back({x[0], ab, ca});
            children.push_back({ab, x[1], bc});
            children.push_back({ca, bc, x[2]});
            children.push_back({ab, bc, ca});
        }
        faces = std::move(children);
        p = std::move(next);
    }

    // The limit surface: positions and normals from the final mesh's rings.
    Topology t(std::move(faces), p.size());
    SubdividedMesh out;
    out.p.resize(p.size());
    out.n.resize(p.size());
    for (int v = 0; v < int(p.size()); ++v) {
        Point3f pv = p[std::size_t(v)];
        bool boundary = t.ring(v, &ring);
        int n = int(ring.size());
        if (n == 0) {
            out.p[std::size_t(v)] = pv;
            continue;
        }
        out.p[std::size_t(v)] = boundary
                                    ? boundary_weighted(pv, ring, p, 1.0f / 5)
                                    : one_ring_weighted(pv, ring, p, 1 / (float(n) + 3 / (8 * loop_beta(n))));
        auto r = [&](int j) { return Vector3f(p[std::size_t(ring[std::size_t(j)])]); };
        Vector3f s, tt;
        if (!boundary) {
            for (int j = 0; j < n; ++j) {
                float th = 2 * kPi * float(j) / float(n);
                s += r(j) * std::cos(th);
                tt += r(j) * std::sin(th);
            }
        } else {
            s = r(n - 1) - r(0);
            Vector3f c(pv);
            if (n == 2)
                tt = r(0) + r(1) - c * 2;
            else if (n == 3)
                tt = r(1) - c;
            else if (n == 4)
                tt = r(0) * -1 + r(1) * 2 + r(2) * 2 - r(3) - c * 2; // regular
            else {
                float th = kPi / float(n - 1);
                tt = (r(0) + r(n - 1)) * std::sin(th);
                for (int k = 1; k < n - 1; ++k)
                    tt += r(k) * ((2 * std::cos(th) - 2) * std::sin(float(k) * th));
                tt = -tt;
            }
        }
        Vector3f nv = cross(s, tt);
        if (!(length_squared(nv) > 0)) {
            // A degenerate ring (pbrt-v4 leaves a zero normal): the faces' normals summed, on the side the
            // tangents' normals take (against the winding).
            int f = t.vertex_face[std::size_t(v)];
            const Face& x = t.faces[std::size_t(f)];
            Vector3f e1 = p[std::size_t(x[1])] - p[std::size_t(x[0])],
                     e2 = p[std::size_t(x[2])] - p[std::size_t(x[0])];
            nv = -cross(e1, e2);
            if (!(length_squared(nv) > 0)) nv = {0, 0, 1};
        }
        out.n[std::size_t(v)] = Normal3f(nv);
    }
    out.indices.reserve(3 * t.faces.size());
    for (const Face& f : t.faces)
        for (int v : f) out.indices.push_back(std::uint32_t(v));
    return out;
}

} // namespace illum
