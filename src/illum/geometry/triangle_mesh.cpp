#include "illum/geometry/triangle_mesh.h"

#include "illum/math/warp.h"

namespace illum {

float TriangleMesh::triangle_area(std::size_t tri) const {
    auto v = vertices(tri);
    return 0.5f * length(cross(v[1] - v[0], v[2] - v[0]));
}

void TriangleMesh::transform(const Transform& world_from_object) {
    for (auto& q : p) q = world_from_object(q);
    for (auto& m : n) m = normalize(world_from_object(m));
}

Normal3f TriangleMesh::geometric_normal(std::size_t tri, float b0, float b1, float b2) const {
    auto v = vertices(tri);
    Normal3f ng = normalize(Normal3f(cross(v[0] - v[2], v[1] - v[2])));
    if (!n.empty()) {
        Normal3f ns = n[indices[3 * tri]] * b0 + n[indices[3 * tri + 1]] * b1 + n[indices[3 * tri + 2]] * b2;
        ng = face_forward(ng, Vector3f(ns));
    } else if (flip_normal) {
        ng = -ng;
    }
    return ng;
}

void TriangleMesh::fill_hit(std::uint32_t tri, float b1, float b2, float t, const Ray& ray, SurfaceHit* hit) const {
    float b0 = 1 - b1 - b2;
    std::uint32_t i0 = indices[3 * tri], i1 = indices[3 * tri + 1], i2 = indices[3 * tri + 2];
    Point3f p0 = p[i0], p1 = p[i1], p2 = p[i2];
    hit->p = barycentric(p0, p1, p2, b0, b1, b2);
    // Error of the barycentric interpolation: γ_7 Σ |b_i p_i| (PBR 4th ed., §6.8.5).
    hit->p_error = (abs(Vector3f(p0) * b0) + abs(Vector3f(p1) * b1) + abs(Vector3f(p2) * b2)) * gamma_bound(7);
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = geometric_normal(tri, b0, b1, b2);

    Point2f uv0{0, 0}, uv1{1, 0}, uv2{1, 1};
    if (!uv.empty()) {
        uv0 = uv[i0];
        uv1 = uv[i1];
        uv2 = uv[i2];
    }
    hit->uv = {b0 * uv0.x + b1 * uv1.x + b2 * uv2.x, b0 * uv0.y + b1 * uv1.y + b2 * uv2.y};
    // dp/du from the uv parameterisation; a fallback frame when it is degenerate.
    Vector2f duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    Vector3f dp02 = p0 - p2, dp12 = p1 - p2;
    float det = duv02.x * duv12.y - duv02.y * duv12.x;
    Vector3f dpdu{};
    if (std::abs(det) > 1e-9f) {
        dpdu = (dp02 * duv12.y - dp12 * duv02.y) / det;
        if (!is_finite(dpdu)) dpdu = {};
    }
    hit->dpdu = dpdu;
    if (!n.empty()) {
        Normal3f ns = n[i0] * b0 + n[i1] * b1 + n[i2] * b2;
        float len2 = dot(ns, ns);
        hit->ns = len2 > 0 ? ns * (1 / std::sqrt(len2)) : hit->n;
    } else {
        hit->ns = hit->n;
    }
}

Bounds3f TriangleShape::bounds() const {
    Bounds3f b;
    for (auto& v : mesh_->vertices(index_)) b.extend(v);
    return b;
}

ShapeSample TriangleShape::at_barycentrics(float b0, float b1, float b2) const {
    auto v = mesh_->vertices(index_);
    ShapeSample s;
    s.p = barycentric(v[0], v[1], v[2], b0, b1, b2);
    s.p_error = (abs(Vector3f(v[0]) * b0) + abs(Vector3f(v[1]) * b1) + abs(Vector3f(v[2]) * b2)) * gamma_bound(6);
    s.n = mesh_->geometric_normal(index_, b0, b1, b2);
    Point2f uv0{0, 0}, uv1{1, 0}, uv2{1, 1};
    if (!mesh_->uv.empty()) {
        uv0 = mesh_->uv[mesh_->indices[3 * index_]];
        uv1 = mesh_->uv[mesh_->indices[3 * index_ + 1]];
        uv2 = mesh_->uv[mesh_->indices[3 * index_ + 2]];
    }
    s.uv = {b0 * uv0.x + b1 * uv1.x + b2 * uv2.x, b0 * uv0.y + b1 * uv1.y + b2 * uv2.y};
    return s;
}

ShapeSample TriangleShape::sample_area(Point2f u) const {
    auto b = sample_uniform_triangle(u);
    ShapeSample s = at_barycentrics(b[0], b[1], b[2]);
    s.pdf = 1 / area();
    return s;
}

float TriangleShape::solid_angle(Point3f p) const {
    auto v = mesh_->vertices(index_);
    Vector3f a = v[0] - p, b = v[1] - p, c = v[2] - p;
    if (length_squared(a) == 0 || length_squared(b) == 0 || length_squared(c) == 0) return 0;
    return spherical_triangle_area(normalize(a), normalize(b), normalize(c));
}

std::optional<ShapeSample> TriangleShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    float omega = solid_angle(ctx.p);
    if (omega < kMinSphericalSolidAngle || omega > kMaxSphericalSolidAngle) return AreaShape::sample(ctx, u);
    float pdf = 0;
    auto b = sample_spherical_triangle(mesh_->vertices(index_), ctx.p, u, &pdf);
    if (!(pdf > 0)) return std::nullopt;
    ShapeSample s = at_barycentrics(b[0], b[1], b[2]);
    // Use the exact solid angle for the density so sample() and pdf() agree.
    s.pdf = 1 / omega;
    return s;
}

float TriangleShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit, Normal3f n_hit) const {
    float omega = solid_angle(ctx.p);
    if (omega < kMinSphericalSolidAngle || omega > kMaxSphericalSolidAngle)
        return AreaShape::pdf(ctx, wi, p_hit, n_hit);
    return 1 / omega;
}

} // namespace illum
