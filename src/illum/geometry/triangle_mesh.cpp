#include "illum/geometry/triangle_mesh.h"

#include "illum/math/frame.h"
#include "illum/math/warp.h"

namespace illum {

float TriangleMesh::triangle_area(std::size_t tri) const {
    auto v = vertices(tri);
    return 0.5f * length(cross(v[1] - v[0], v[2] - v[0]));
}

void TriangleMesh::transform(const Transform& world_from_object) {
    for (auto& q : p) q = world_from_object(q);
    for (auto& m : n) {
        m = world_from_object(m);
        if (dot(m, m) > 0) m = normalize(m); // a zero normal (pbrt-v4 leaves some) stays zero
    }
}

void TriangleMesh::finalize() {
    hit_triangles_.resize(triangle_count());
    for (std::size_t tri = 0; tri < triangle_count(); ++tri) {
        auto v = vertices(tri);
        Vector3f c = cross(v[0] - v[2], v[1] - v[2]);
        float len2 = length_squared(c);
        Normal3f ng = len2 > 0 ? Normal3f(c / std::sqrt(len2)) : Normal3f{0, 0, 1};
        if (!n.empty()) {
            // pbrt-v4 turns the geometric normal to the side of the shading normals (their sum over the
            // vertices stands for the interpolated one, which may differ in sign only on degenerate input).
            Normal3f ns = n[indices[3 * tri]] + n[indices[3 * tri + 1]] + n[indices[3 * tri + 2]];
            ng = face_forward(ng, Vector3f(ns));
        } else if (flip_normal) {
            ng = -ng;
        }
        hit_triangles_[tri] = {
            {indices[3 * tri], indices[3 * tri + 1], indices[3 * tri + 2]}, ng, face_index(tri)};
    }
    hit_vertices_.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        hit_vertices_[i] = {p[i], n.empty() ? Normal3f{} : n[i], uv.empty() ? Point2f{} : uv[i]};
}

void TriangleMesh::fill_hit(std::uint32_t tri, float b1, float b2, float t, const Ray& ray,
                            SurfaceHit* hit) const {
    float b0 = 1 - b1 - b2;
    const HitTriangle& tr = hit_triangles_[tri];
    const HitVertex &v0 = hit_vertices_[tr.v[0]], &v1 = hit_vertices_[tr.v[1]], &v2 = hit_vertices_[tr.v[2]];
    Point3f p0 = v0.p, p1 = v1.p, p2 = v2.p;
    hit->p = barycentric(p0, p1, p2, b0, b1, b2);
    // Error of the barycentric interpolation: γ_7 Σ |b_i p_i| (PBR 4th ed., §6.8.5).
    hit->p_error =
        (abs(Vector3f(p0) * b0) + abs(Vector3f(p1) * b1) + abs(Vector3f(p2) * b2)) * gamma_bound(7);
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = tr.n;

    Point2f uv0{0, 0}, uv1{1, 0}, uv2{1, 1};
    if (!uv.empty()) {
        uv0 = v0.uv;
        uv1 = v1.uv;
        uv2 = v2.uv;
    }
    hit->uv = {b0 * uv0.x + b1 * uv1.x + b2 * uv2.x, b0 * uv0.y + b1 * uv1.y + b2 * uv2.y};
    hit->face_index = tr.face_index;
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
        Normal3f ns = v0.n * b0 + v1.n * b1 + v2.n * b2;
        float len2 = dot(ns, ns);
        hit->ns = len2 > 0 ? ns * (1 / std::sqrt(len2)) : hit->n;
    } else {
        hit->ns = hit->n;
    }
    hit->partials_source = this;
    hit->local = {b1, b2, 0};
}

ShadingPartials TriangleMesh::shading_partials(std::uint32_t tri, Point3f local) const {
    float b1 = local.x, b2 = local.y, b0 = 1 - b1 - b2;
    std::uint32_t i0 = indices[3 * tri], i1 = indices[3 * tri + 1], i2 = indices[3 * tri + 2];
    Point2f uv0{0, 0}, uv1{1, 0}, uv2{1, 1};
    if (!uv.empty()) {
        uv0 = uv[i0];
        uv1 = uv[i1];
        uv2 = uv[i2];
    }
    // ∂p/∂u, ∂p/∂v solve [duv02; duv12] [∂p/∂u; ∂p/∂v] = [dp02; dp12]; an arbitrary frame around the face
    // normal when the uv parameterisation is degenerate (pbrt-v4's Triangle).
    Vector2f duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    Vector3f dp02 = p[i0] - p[i2], dp12 = p[i1] - p[i2];
    float det = duv02.x * duv12.y - duv02.y * duv12.x;
    bool degenerate_uv = !(std::abs(det) >= 1e-9f);
    ShadingPartials s;
    bool degenerate = degenerate_uv;
    if (!degenerate_uv) {
        float inv = 1 / det;
        s.dpdu = (dp02 * duv12.y - dp12 * duv02.y) * inv;
        s.dpdv = (dp12 * duv02.x - dp02 * duv12.x) * inv;
        degenerate = !is_finite(s.dpdu) || !is_finite(s.dpdv) || length_squared(cross(s.dpdu, s.dpdv)) == 0;
    }
    if (degenerate) coordinate_system(Vector3f(geometric_normal(tri)), &s.dpdu, &s.dpdv);
    s.geometric_dpdu = s.dpdu, s.geometric_dpdv = s.dpdv;
    if (n.empty()) return s; // ∂n/∂u = ∂n/∂v = 0

    // With vertex normals: ∂p/∂u made orthogonal to the interpolated normal ns, ∂p/∂v = ns × ∂p/∂u, and
    // ∂n/∂u, ∂n/∂v from the normals as ∂p/∂u, ∂p/∂v from the points.
    Normal3f ns = n[i0] * b0 + n[i1] * b1 + n[i2] * b2;
    float len2 = dot(ns, ns);
    Vector3f z = len2 > 0 ? Vector3f(ns) * (1 / std::sqrt(len2)) : Vector3f(geometric_normal(tri));
    Vector3f ts = cross(z, s.dpdu);
    if (length_squared(ts) > 0) {
        s.dpdu = cross(ts, z);
        s.dpdv = ts;
    } else {
        coordinate_system(z, &s.dpdu, &s.dpdv);
    }
    Vector3f dn1 = Vector3f(n[i0]) - Vector3f(n[i2]), dn2 = Vector3f(n[i1]) - Vector3f(n[i2]);
    if (!degenerate_uv) {
        float inv = 1 / det;
        s.dndu = Normal3f((dn1 * duv12.y - dn2 * duv02.y) * inv);
        s.dndv = Normal3f((dn2 * duv02.x - dn1 * duv12.x) * inv);
    } else {
        // pbrt-v4: the derivatives in an arbitrary frame around the normals' cross product.
        Vector3f dn = cross(Vector3f(n[i2]) - Vector3f(n[i0]), Vector3f(n[i1]) - Vector3f(n[i0]));
        if (length_squared(dn) > 0) {
            Vector3f dnu, dnv;
            coordinate_system(normalize(dn), &dnu, &dnv);
            s.dndu = Normal3f(dnu);
            s.dndv = Normal3f(dnv);
        }
    }
    return s;
}

TriangleShape::TriangleShape(const TriangleMesh* mesh, std::uint32_t index)
    : mesh_(mesh), index_(index), v_(mesh->vertices(index)) {
    const auto& v = v_;
    if (!mesh_->uv.empty())
        for (int k = 0; k < 3; ++k)
            uv_[std::size_t(k)] = mesh_->uv[mesh_->indices[3 * index_ + std::uint32_t(k)]];
    area_normal_ = cross(v[1] - v[0], v[2] - v[0]);
    area_ = 0.5f * length(area_normal_);
    centroid_ = Point3f((Vector3f(v[0]) + Vector3f(v[1]) + Vector3f(v[2])) / 3);
}

Bounds3f TriangleShape::bounds() const {
    Bounds3f b;
    for (const Point3f& v : v_) b.extend(v);
    return b;
}

ShapePoint TriangleShape::at_barycentrics(float b0, float b1, float b2) const {
    const auto& v = v_;
    ShapePoint s;
    s.p = barycentric(v[0], v[1], v[2], b0, b1, b2);
    s.p_error =
        (abs(Vector3f(v[0]) * b0) + abs(Vector3f(v[1]) * b1) + abs(Vector3f(v[2]) * b2)) * gamma_bound(6);
    s.n = mesh_->geometric_normal(index_);
    const Point2f &uv0 = uv_[0], &uv1 = uv_[1], &uv2 = uv_[2];
    s.uv = {b0 * uv0.x + b1 * uv1.x + b2 * uv2.x, b0 * uv0.y + b1 * uv1.y + b2 * uv2.y};
    return s;
}

AreaShapeSample TriangleShape::sample_area(Point2f u) const {
    auto b = sample_uniform_triangle(u);
    return {at_barycentrics(b[0], b[1], b[2]), AreaPdf(1 / area_)};
}

bool TriangleShape::use_spherical_sampling(Point3f p) const {
    // A cheap planar estimate of the solid angle, Ω ≈ A |cos θ| / d² at the centroid, decides the strategy
    // where it is accurate (small Ω); close to the triangle it overshoots (it grows without bound), so there
    // the exact Ω decides. sample() and pdf() decide from this one function, so they always agree.
    Vector3f d = centroid_ - p;
    float d2 = length_squared(d);
    float estimate = 0.5f * std::abs(dot(area_normal_, d)) / (d2 * std::sqrt(d2));
    if (!(estimate >= kMinSphericalSolidAngle)) return false;
    if (estimate <= 1.0f) return true;
    float pdf = spherical_triangle_pdf(v_, p);
    return pdf > 0 && 1 / pdf <= kMaxSphericalSolidAngle;
}

std::optional<ShapeSample> TriangleShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    if (!use_spherical_sampling(ctx.p)) return AreaShape::sample(ctx, u);
    float pdf = 0;
    auto b = sample_spherical_triangle(v_, ctx.p, u, &pdf);
    if (!(pdf > 0)) return std::nullopt; // degenerate as seen from p: no solid angle to sample
    return seen_from(ctx.p, at_barycentrics(b[0], b[1], b[2]), SolidAnglePdf(pdf));
}

SolidAnglePdf TriangleShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                                 Normal3f n_hit) const {
    if (!use_spherical_sampling(ctx.p)) return AreaShape::pdf(ctx, wi, p_hit, n_hit);
    // Uniform over the spherical triangle: 1 / Ω (Arvo 1995).
    return SolidAnglePdf(spherical_triangle_pdf(v_, ctx.p));
}

} // namespace illum
