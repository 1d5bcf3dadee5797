#include "illum/geometry/bilinear_patch.h"

#include <algorithm>
#include <cmath>

#include "illum/math/bilinear_warp.h"
#include "illum/math/frame.h"
#include "illum/math/spherical_rectangle.h"

namespace illum {

namespace {

Point3f bilerp(const std::array<Point3f, 4>& c, float u, float v) {
    return lerp(u, lerp(v, c[0], c[2]), lerp(v, c[1], c[3]));
}
Vector3f dpdu_at(const std::array<Point3f, 4>& c, float v) {
    return lerp(v, c[1], c[3]) - lerp(v, c[0], c[2]);
}
Vector3f dpdv_at(const std::array<Point3f, 4>& c, float u) {
    return lerp(u, c[2], c[3]) - lerp(u, c[0], c[1]);
}
float max_abs_component(Vector3f v) { return max_component(abs(v)); }

// The scalar triple product a · (b × c): the determinant of the matrix of columns a, b, c.
float triple(Vector3f a, Vector3f b, Vector3f c) { return dot(a, cross(b, c)); }

// The real roots of a x² + b x + c = 0 (double precision, the cancellation-free form); how many.
int quadratic_roots(double a, double b, double c, double* x0, double* x1) {
    if (a == 0) {
        if (b == 0) return 0;
        *x0 = *x1 = -c / b;
        return 1;
    }
    double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = q != 0 ? c / q : r0;
    *x0 = std::min(r0, r1);
    *x1 = std::max(r0, r1);
    return 2;
}

// Rotates v by the rotation that takes the unit vector a to the unit vector b (Rodrigues' formula about
// a × b); pbrt-v4's RotateFromTo, which carries ∂p/∂u, ∂p/∂v to the shading normal.
Vector3f rotate_from_to(Vector3f a, Vector3f b, Vector3f v) {
    Vector3f k = cross(a, b);
    float s = length(k), c = dot(a, b);
    if (!(s > 1e-7f)) return c > 0 ? v : -v;
    k = k / s;
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

// Gauss-Legendre nodes and weights of order 8 on [0, 1].
constexpr double kGlX[8] = {0.019855071751231856, 0.10166676129318664, 0.2372337950418355,
                            0.4082826787521751,   0.5917173212478249,  0.7627662049581645,
                            0.8983332387068134,   0.9801449282487681};
constexpr double kGlW[8] = {0.05061426814518813, 0.11119051722668724, 0.15685332293894364,
                            0.18134189168918100, 0.18134189168918100, 0.15685332293894364,
                            0.11119051722668724, 0.05061426814518813};

} // namespace

std::optional<PatchCrossing> intersect_bilinear_patch(Point3f o, Vector3f d, float tmax, Point3f p00,
                                                      Point3f p10, Point3f p01, Point3f p11) {
    // The ray meets the u-isoline through lerp(u, p00, p10) and lerp(u, p01, p11) where the distance from
    // the ray to it vanishes: a u² + b u + c = 0 (Reshetov 2019, eq. 8).
    double a = dot(cross(p10 - p00, p01 - p11), d);
    double c = dot(cross(p00 - o, d), p01 - p00);
    double b = dot(cross(p10 - o, d), p11 - p10) - (a + c);
    double u_root[2];
    int n = quadratic_roots(a, b, c, &u_root[0], &u_root[1]);
    if (n == 0) return std::nullopt;
    // Crossings nearer than this are within the rounding of the arithmetic below (pbrt-v4's bound).
    float eps = gamma_bound(30) * (max_abs_component(Vector3f(o)) + max_abs_component(d) +
                                   max_abs_component(Vector3f(p00)) + max_abs_component(Vector3f(p10)) +
                                   max_abs_component(Vector3f(p01)) + max_abs_component(Vector3f(p11)));
    std::optional<PatchCrossing> best;
    float t_best = tmax;
    for (int i = 0; i < n; ++i) {
        if (i == 1 && u_root[1] == u_root[0]) break;
        float u = float(u_root[i]);
        if (!(u >= 0 && u <= 1)) continue;
        // Closest approach of the ray and the isoline q(v) = uo + v ud: solve o + t d - q(v) ∥ d × ud by
        // Cramer's rule, v = det(Δ, d, d × ud) / |d × ud|², t = det(Δ, ud, d × ud) / |d × ud|².
        Point3f uo = lerp(u, p00, p10);
        Vector3f ud = lerp(u, p01, p11) - uo, delta = uo - o, perp = cross(d, ud);
        float p2 = length_squared(perp);
        float v_num = triple(delta, d, perp), t_num = triple(delta, ud, perp);
        if (!(p2 > 0) || !(v_num >= 0 && v_num <= p2)) continue;
        float t = t_num / p2;
        if (!(t > eps && t < t_best)) continue;
        t_best = t;
        best = PatchCrossing{u, v_num / p2, t};
    }
    return best;
}

Bounds3f BilinearPatchMesh::patch_bounds(std::size_t patch) const {
    Bounds3f b;
    for (Point3f c : corners(patch)) b.extend(c);
    return b;
}

void BilinearPatchMesh::transform(const Transform& world_from_object, bool reverse_orientation) {
    for (auto& q : p) q = world_from_object(q);
    for (auto& m : n) {
        m = world_from_object(m);
        if (reverse_orientation) m = -m;
    }
}

void BilinearPatchMesh::finalize() {
    // pbrt-v4's IsRectangle: no two consecutive corners equal, p11 in the plane of the other three (to
    // 1e-5 in the cosine), and all corners at the same distance from their centroid (to 1e-4, relative).
    rectangle.assign(patch_count(), 0);
    for (std::size_t i = 0; i < patch_count(); ++i) {
        auto c = corners(i);
        if (c[0] == c[2] || c[2] == c[3] || c[3] == c[1] || c[1] == c[0]) continue;
        Vector3f nrm = normalize(cross(c[1] - c[0], c[2] - c[0]));
        if (std::abs(dot(normalize(c[3] - c[0]), nrm)) > 1e-5f) continue;
        Point3f centre = Point3f((Vector3f(c[0]) + Vector3f(c[1]) + Vector3f(c[2]) + Vector3f(c[3])) / 4);
        float d0 = distance_squared(c[0], centre);
        bool equal = d0 > 0;
        for (int k = 1; k < 4 && equal; ++k)
            equal = std::abs(distance_squared(c[std::size_t(k)], centre) - d0) / d0 <= 1e-4f;
        rectangle[i] = equal;
    }
}

Point2f BilinearPatchMesh::texture_uv(std::size_t patch, float u, float v) const {
    if (uv.empty()) return {u, v};
    const std::uint32_t* k = &indices[4 * patch];
    Point2f a = uv[k[0]], b = uv[k[1]], c = uv[k[2]], d = uv[k[3]];
    auto l = [](float t, Point2f x, Point2f y) {
        return Point2f{x.x + (y.x - x.x) * t, x.y + (y.y - x.y) * t};
    };
    return l(u, l(v, a, c), l(v, b, d));
}

Normal3f BilinearPatchMesh::shading_normal(std::size_t patch, float u, float v) const {
    if (n.empty()) return {};
    const std::uint32_t* k = &indices[4 * patch];
    return n[k[0]] * ((1 - u) * (1 - v)) + n[k[1]] * (u * (1 - v)) + n[k[2]] * ((1 - u) * v) +
           n[k[3]] * (u * v);
}

Normal3f BilinearPatchMesh::geometric_normal(std::size_t patch, float u, float v) const {
    auto c = corners(patch);
    Vector3f g = cross(dpdu_at(c, v), dpdv_at(c, u));
    // At a corner where two vertices coincide ∂p/∂u × ∂p/∂v vanishes; the cross product of the diagonals
    // has the same orientation.
    if (!(length_squared(g) > 0)) g = cross(c[3] - c[0], c[2] - c[1]);
    float len2 = length_squared(g);
    Normal3f ng = len2 > 0 ? Normal3f(g / std::sqrt(len2)) : Normal3f{0, 0, 1};
    if (!n.empty()) return face_forward(ng, Vector3f(shading_normal(patch, u, v)));
    return flip_normal ? -ng : ng;
}

Vector3f BilinearPatchMesh::point_error(std::size_t patch) const {
    auto c = corners(patch);
    return (abs(c[0]) + abs(c[1]) + abs(c[2]) + abs(c[3])) * gamma_bound(6);
}

namespace {

// ∂p/∂s, ∂p/∂t of the texture parameterisation and the factors pbrt-v4 carries ∂/∂u, ∂/∂v to ∂/∂s, ∂/∂t
// with (each ∂u/∂s taken as 1 / (∂s/∂u), 0 where that is below 1e-8).
struct TextureFrame {
    Vector3f dpdu, dpdv;
    float duds = 1, dudt = 0, dvds = 0, dvdt = 1;
};

TextureFrame texture_frame(const BilinearPatchMesh& m, std::size_t patch, float u, float v) {
    auto c = m.corners(patch);
    TextureFrame f{dpdu_at(c, v), dpdv_at(c, u)};
    if (m.uv.empty()) return f;
    const std::uint32_t* k = &m.indices[4 * patch];
    Point2f a = m.uv[k[0]], b = m.uv[k[1]], cc = m.uv[k[2]], d = m.uv[k[3]];
    Vector2f dstdu{(1 - v) * (b.x - a.x) + v * (d.x - cc.x), (1 - v) * (b.y - a.y) + v * (d.y - cc.y)};
    Vector2f dstdv{(1 - u) * (cc.x - a.x) + u * (d.x - b.x), (1 - u) * (cc.y - a.y) + u * (d.y - b.y)};
    auto inv = [](float x) { return std::abs(x) < 1e-8f ? 0.0f : 1 / x; };
    f.duds = inv(dstdu.x);
    f.dvds = inv(dstdv.x);
    f.dudt = inv(dstdu.y);
    f.dvdt = inv(dstdv.y);
    Vector3f dpds = f.dpdu * f.duds + f.dpdv * f.dvds, dpdt = f.dpdu * f.dudt + f.dpdv * f.dvdt;
    Vector3f nst = cross(dpds, dpdt);
    if (length_squared(nst) > 0) {
        if (dot(cross(f.dpdu, f.dpdv), nst) < 0) dpdt = -dpdt;
        f.dpdu = dpds;
        f.dpdv = dpdt;
    }
    return f;
}

} // namespace

void BilinearPatchMesh::fill_hit(std::uint32_t patch, float u, float v, float t, const Ray& ray,
                                 SurfaceHit* hit) const {
    auto c = corners(patch);
    hit->p = bilerp(c, u, v);
    hit->p_error = point_error(patch);
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = geometric_normal(patch, u, v);
    hit->uv = texture_uv(patch, u, v);
    hit->face_index = face_index(patch);
    hit->dpdu = texture_frame(*this, patch, u, v).dpdu;
    Normal3f ns = shading_normal(patch, u, v);
    float len2 = dot(ns, ns);
    hit->ns = len2 > 0 ? ns * (1 / std::sqrt(len2)) : hit->n;
    hit->partials_source = this;
    hit->local = {u, v, 0};
}

ShadingPartials BilinearPatchMesh::shading_partials(std::uint32_t patch, Point3f local) const {
    float u = local.x, v = local.y;
    auto c = corners(patch);
    TextureFrame f = texture_frame(*this, patch, u, v);
    ShadingPartials s{f.dpdu, f.dpdv, {}, {}, f.dpdu, f.dpdv};
    // Weingarten: with ∂²p/∂u² = ∂²p/∂v² = 0 the second fundamental form has e = g = 0 and
    // f = n · ∂²p/∂u∂v; ∂n/∂u = (f F - e G) / (EG - F²) ∂p/∂u + (e F - f E) / (EG - F²) ∂p/∂v, and ∂n/∂v
    // likewise (PBR 4th ed. eq. 6.4), in the parameterisation of ∂p/∂u, ∂p/∂v, then carried to (s, t).
    Vector3f d2p = (c[0] - c[2]) + (c[3] - c[1]);
    float E = dot(f.dpdu, f.dpdu), F = dot(f.dpdu, f.dpdv), G = dot(f.dpdv, f.dpdv);
    Vector3f nrm = cross(f.dpdu, f.dpdv);
    if (length_squared(nrm) > 0) {
        nrm = normalize(nrm);
        float ff = dot(nrm, d2p);
        float egf2 = E * G - F * F, inv = egf2 == 0 ? 0 : 1 / egf2;
        Normal3f dndu(f.dpdu * (ff * F * inv) + f.dpdv * (-ff * E * inv));
        Normal3f dndv(f.dpdu * (-ff * G * inv) + f.dpdv * (ff * F * inv));
        s.dndu = dndu * f.duds + dndv * f.dvds;
        s.dndv = dndu * f.dudt + dndv * f.dvdt;
    } else {
        coordinate_system(Vector3f(geometric_normal(patch, u, v)), &s.dpdu, &s.dpdv);
    }
    if (n.empty()) return s;
    Normal3f ns = shading_normal(patch, u, v);
    if (!(dot(ns, ns) > 0)) return s;
    // With vertex normals (pbrt-v4): ∂n/∂u, ∂n/∂v are the normals' bilinear derivatives carried to (s, t),
    // and ∂p/∂u, ∂p/∂v turn with the rotation from the geometric to the shading normal.
    const std::uint32_t* k = &indices[4 * patch];
    Normal3f n00 = n[k[0]], n10 = n[k[1]], n01 = n[k[2]], n11 = n[k[3]];
    Normal3f dndu = (n10 * (1 - v) + n11 * v) + -(n00 * (1 - v) + n01 * v);
    Normal3f dndv = (n01 * (1 - u) + n11 * u) + -(n00 * (1 - u) + n10 * u);
    s.dndu = dndu * f.duds + dndv * f.dvds;
    s.dndv = dndu * f.dudt + dndv * f.dvdt;
    Vector3f from(geometric_normal(patch, u, v)), to(normalize(ns));
    s.dpdu = rotate_from_to(from, to, s.dpdu);
    s.dpdv = rotate_from_to(from, to, s.dpdv);
    return s;
}

BilinearPatchShape::BilinearPatchShape(const BilinearPatchMesh* mesh, std::uint32_t index)
    : mesh_(mesh), index_(index) {
    auto c = mesh_->corners(index_);
    if (is_rectangle()) {
        area_ = distance(c[0], c[2]) * distance(c[0], c[1]);
        return;
    }
    double sum = 0;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            sum += kGlW[i] * kGlW[j] *
                   double(length(cross(dpdu_at(c, float(kGlX[j])), dpdv_at(c, float(kGlX[i])))));
    area_ = float(sum);
}

float BilinearPatchShape::area_density(Point2f uv) const {
    auto c = mesh_->corners(index_);
    float jac = length(cross(dpdu_at(c, uv.y), dpdv_at(c, uv.x)));
    if (!(jac > 0)) return 0;
    if (mesh_->emission_distribution) return mesh_->emission_distribution->pdf(uv) / jac;
    if (is_rectangle()) return 1 / jac;
    // The corner weights: |∂p/∂u × ∂p/∂v| at (0,0), (1,0), (0,1), (1,1).
    std::array<float, 4> w = {
        length(cross(c[1] - c[0], c[2] - c[0])), length(cross(c[1] - c[0], c[3] - c[1])),
        length(cross(c[2] - c[0], c[3] - c[2])), length(cross(c[3] - c[1], c[3] - c[2]))};
    return bilinear_pdf(uv, w) / jac;
}

ShapePoint BilinearPatchShape::point_at(Point2f uv) const {
    ShapePoint s;
    s.p = bilerp(mesh_->corners(index_), uv.x, uv.y);
    s.p_error = mesh_->point_error(index_);
    s.n = mesh_->geometric_normal(index_, uv.x, uv.y);
    s.uv = mesh_->texture_uv(index_, uv.x, uv.y);
    return s;
}

AreaShapeSample BilinearPatchShape::sample_area(Point2f u) const {
    Point2f uv = u;
    if (mesh_->emission_distribution) {
        uv = mesh_->emission_distribution->sample(u);
    } else if (!is_rectangle()) {
        auto c = mesh_->corners(index_);
        std::array<float, 4> w = {
            length(cross(c[1] - c[0], c[2] - c[0])), length(cross(c[1] - c[0], c[3] - c[1])),
            length(cross(c[2] - c[0], c[3] - c[2])), length(cross(c[3] - c[1], c[3] - c[2]))};
        uv = sample_bilinear(u, w);
    }
    return {point_at(uv), AreaPdf(area_density(uv))};
}

Point2f BilinearPatchShape::patch_uv(Point3f p) const {
    auto c = mesh_->corners(index_);
    // Gauss-Newton on |p(u, v) - p|², from the centre, clamped to the unit square; exact in two steps for a
    // parallelogram, quadratic convergence otherwise.
    double u = 0.5, v = 0.5;
    for (int it = 0; it < 12; ++it) {
        Vector3f r = bilerp(c, float(u), float(v)) - p;
        Vector3f du = dpdu_at(c, float(v)), dv = dpdv_at(c, float(u));
        double a = dot(du, du), b = dot(du, dv), d = dot(dv, dv), ru = dot(du, r), rv = dot(dv, r);
        double det = a * d - b * b;
        if (!(det > 0)) break;
        double step_u = (d * ru - b * rv) / det, step_v = (a * rv - b * ru) / det;
        u = std::clamp(u - step_u, 0.0, 1.0);
        v = std::clamp(v - step_v, 0.0, 1.0);
        if (std::abs(step_u) + std::abs(step_v) < 1e-7) break;
    }
    return {float(u), float(v)};
}

AreaPdf BilinearPatchShape::area_pdf(Point3f p) const { return AreaPdf(area_density(patch_uv(p))); }

namespace {

// pbrt-v4's weights for warping a rectangle's spherical sample by the receiver's cosine: |cos| towards
// each corner (00, 10, 01, 11), at least 0.01.
std::array<float, 4> cosine_weights(const std::array<Point3f, 4>& c, const ShapeSampleContext& ctx) {
    std::array<float, 4> w;
    for (std::size_t k = 0; k < 4; ++k)
        w[k] = std::max(0.01f, abs_dot(normalize(c[k] - ctx.p), Vector3f(ctx.n)));
    return w;
}

} // namespace

std::optional<ShapeSample> BilinearPatchShape::sample(const ShapeSampleContext& ctx, Point2f u) const {
    if (!samples_solid_angle()) return AreaShape::sample(ctx, u);
    auto c = mesh_->corners(index_);
    Vector3f eu = c[1] - c[0], ev = c[2] - c[0];
    if (spherical_rectangle_solid_angle(ctx.p, c[0], eu, ev) <= kMinSphericalSolidAngle)
        return AreaShape::sample(ctx, u);
    float pdf = 1;
    if (ctx.n != Normal3f{}) {
        std::array<float, 4> w = cosine_weights(c, ctx);
        u = sample_bilinear(u, w);
        pdf = bilinear_pdf(u, w);
    }
    auto s = sample_spherical_rectangle(ctx.p, c[0], eu, ev, u);
    if (!s) return std::nullopt;
    Point2f uv{std::clamp(dot(s->p - c[0], eu) / length_squared(eu), 0.0f, 1.0f),
               std::clamp(dot(s->p - c[0], ev) / length_squared(ev), 0.0f, 1.0f)};
    ShapePoint pt = point_at(uv);
    pt.p = s->p;
    return seen_from(ctx.p, pt, SolidAnglePdf(pdf * s->pdf));
}

SolidAnglePdf BilinearPatchShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                                      Normal3f n_hit) const {
    if (samples_solid_angle()) {
        auto c = mesh_->corners(index_);
        Vector3f eu = c[1] - c[0], ev = c[2] - c[0];
        float solid_angle = spherical_rectangle_solid_angle(ctx.p, c[0], eu, ev);
        if (solid_angle > kMinSphericalSolidAngle) {
            float pdf = 1 / solid_angle;
            if (ctx.n != Normal3f{})
                pdf *= bilinear_pdf(invert_spherical_rectangle_sample(ctx.p, c[0], eu, ev, p_hit),
                                    cosine_weights(c, ctx));
            return SolidAnglePdf(pdf);
        }
    }
    return area_pdf_to_solid_angle(area_pdf(p_hit), ctx.p, p_hit, n_hit, wi);
}

} // namespace illum
