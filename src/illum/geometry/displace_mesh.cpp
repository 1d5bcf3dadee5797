#include "illum/geometry/displace_mesh.h"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

#include "illum/util/error.h"

namespace illum {

std::vector<Normal3f> vertex_normals(const TriangleMesh& mesh) {
    std::vector<Vector3f> sum(mesh.p.size());
    for (std::size_t f = 0; f < mesh.triangle_count(); ++f) {
        const std::uint32_t* v = &mesh.indices[3 * f];
        Vector3f c = cross(mesh.p[v[1]] - mesh.p[v[0]], mesh.p[v[2]] - mesh.p[v[1]]);
        float len2 = length_squared(c);
        if (!(len2 > 0)) continue;
        c = c / std::sqrt(len2);
        for (int k = 0; k < 3; ++k) sum[v[k]] += c;
    }
    std::vector<Normal3f> n(mesh.p.size());
    for (std::size_t i = 0; i < n.size(); ++i) {
        float len2 = length_squared(sum[i]);
        n[i] = len2 > 0 ? Normal3f(sum[i] / std::sqrt(len2)) : Normal3f{};
    }
    return n;
}

void refine_to_edge_length(TriangleMesh& mesh, const Transform& world_from_object, float max_edge,
                           std::size_t max_triangles) {
    std::vector<Point3f> world(mesh.p.size());
    for (std::size_t i = 0; i < mesh.p.size(); ++i) world[i] = world_from_object(mesh.p[i]);
    std::vector<std::uint32_t> input = std::move(mesh.indices);
    mesh.indices.clear();
    // Each piece keeps the face index of the triangle it comes from.
    std::vector<int> input_faces = std::move(mesh.face_indices);
    mesh.face_indices.clear();
    // The midpoint vertex of each split edge (keyed by its ends, smaller first).
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
    std::vector<std::array<std::uint32_t, 3>> stack;
    for (std::size_t f = 0; f + 2 < input.size(); f += 3) {
        // Depth first, the first half before the second, as pbrt-v4's recursive Refine.
        stack.push_back({input[f], input[f + 1], input[f + 2]});
        while (!stack.empty()) {
            auto [v0, v1, v2] = stack.back();
            stack.pop_back();
            float d01 = distance(world[v0], world[v1]), d12 = distance(world[v1], world[v2]),
                  d20 = distance(world[v2], world[v0]);
            if (d01 < max_edge && d12 < max_edge && d20 < max_edge) {
                mesh.indices.insert(mesh.indices.end(), {v0, v1, v2});
                if (!input_faces.empty()) mesh.face_indices.push_back(input_faces[f / 3]);
                if (mesh.indices.size() / 3 > max_triangles)
                    throw Error(
                        fmt::format("displacement refines the mesh beyond {} triangles (edge length {})",
                                    max_triangles, max_edge));
                continue;
            }
            if (!(std::isfinite(d01) && std::isfinite(d12) && std::isfinite(d20)))
                throw Error("displacement: the mesh has a vertex that is not finite");
            // Rotate so that (a, b) is the longest edge.
            std::array<std::uint32_t, 3> v;
            if (d01 > d12)
                v = d01 > d20 ? std::array{v0, v1, v2} : std::array{v2, v0, v1};
            else
                v = d12 > d20 ? std::array{v1, v2, v0} : std::array{v2, v0, v1};
            std::uint32_t lo = std::min(v[0], v[1]), hi = std::max(v[0], v[1]);
            auto [it, fresh] =
                midpoint.try_emplace((std::uint64_t(lo) << 32) | hi, std::uint32_t(mesh.p.size()));
            if (fresh) {
                mesh.p.push_back(Point3f((Vector3f(mesh.p[v[0]]) + Vector3f(mesh.p[v[1]])) * 0.5f));
                world.push_back(Point3f((Vector3f(world[v[0]]) + Vector3f(world[v[1]])) * 0.5f));
                if (!mesh.n.empty()) {
                    Normal3f nn = mesh.n[v[0]] + mesh.n[v[1]];
                    float len2 = dot(nn, nn);
                    mesh.n.push_back(len2 > 0 ? nn * (1 / std::sqrt(len2)) : nn);
                }
                if (!mesh.uv.empty()) {
                    Point2f a = mesh.uv[v[0]], b = mesh.uv[v[1]];
                    mesh.uv.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2});
                }
            }
            std::uint32_t mid = it->second;
            stack.push_back({mid, v[1], v[2]}); // second half
            stack.push_back({v[0], mid, v[2]}); // first half, refined first
        }
    }
}

void displace_mesh(TriangleMesh& mesh, const FloatTexture& displacement, const Transform& world_from_object,
                   float max_edge, std::size_t max_triangles) {
    if (mesh.n.empty()) mesh.n = vertex_normals(mesh);
    refine_to_edge_length(mesh, world_from_object, max_edge, max_triangles);
    for (std::size_t i = 0; i < mesh.p.size(); ++i) {
        TextureEvalContext ctx;
        ctx.p = mesh.p[i]; // object space, as pbrt-v4 evaluates it
        ctx.uv = mesh.uv[i];
        float d = displacement.evaluate(ctx);
        mesh.p[i] += Vector3f(mesh.n[i]) * d;
    }
    mesh.n = vertex_normals(mesh);
}

} // namespace illum
