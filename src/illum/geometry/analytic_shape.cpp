#include "illum/geometry/analytic_shape.h"

#include <algorithm>
#include <array>

namespace illum {

namespace {

// Gauss-Legendre nodes and weights on [0, 1] (Newton's iteration on P_n from the asymptotic guess
// cos(π (i - 1/4) / (n + 1/2)); Numerical Recipes §4.6).
template <int N>
struct GaussLegendre {
    std::array<double, N> x{}, w{};
    GaussLegendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(kPiD * (i + 0.75) / (N + 0.5)), dp = 1;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = 0;
                for (int j = 0; j < N; ++j) {
                    double p2 = p1;
                    p1 = p0;
                    p0 = ((2 * j + 1) * z * p1 - j * p2) / (j + 1);
                }
                dp = N * (z * p0 - p1) / (z * z - 1);
                double dz = p0 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-15) break;
            }
            x[i] = 0.5 * (1 - z);
            w[i] = 1 / ((1 - z * z) * dp * dp); // 2 / ((1 - z²) P'²) halved for [0, 1]
        }
    }
};

} // namespace

AnalyticShape::AnalyticShape(const Transform& world_from_object, bool flip_normal)
    : world_from_object_(world_from_object), flip_(flip_normal) {
    const Matrix4& m = world_from_object_.matrix();
    det_ = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
           m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
    // A similarity has MᵀM = s² I.
    double g[3][3], trace = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            g[i][j] = m(0, i) * m(0, j) + m(1, i) * m(1, j) + m(2, i) * m(2, j);
            if (i == j) trace += g[i][j];
        }
    double s2 = trace / 3;
    similarity_ = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-6 * s2) similarity_ = false;
    scale_ = std::sqrt(s2);
}

void AnalyticShape::init_area() {
    // The culling bounds: the world bounds widened by 1e-4 of their size and magnitude, far beyond the float
    // rounding of the corners and of the slab test, so that no ray that crosses the surface is culled.
    Bounds3f b = bounds();
    if (!b.empty()) {
        cull_valid_ = true;
        for (int a = 0; a < 3; ++a) {
            float pad = (b.hi[a] - b.lo[a] + std::max(std::abs(b.lo[a]), std::abs(b.hi[a]))) * 1e-4f;
            cull_.lo[a] = b.lo[a] - pad;
            cull_.hi[a] = b.hi[a] + pad;
            cull_valid_ = cull_valid_ && std::isfinite(cull_.lo[a]) && std::isfinite(cull_.hi[a]);
        }
    }
    if (similarity_) {
        area_ = float(scale_ * scale_ * object_area());
        return;
    }
    // A = A_obj ∫∫ J(p(u)) du over the unit square. The substitution u = (1 - cos πs) / 2 in both
    // coordinates removes the square-root endpoint behaviour of the samplers' maps (sphere poles, disk
    // centre), so Gauss-Legendre in s converges fast.
    static const GaussLegendre<48> gl;
    double sum = 0;
    for (int i = 0; i < 48; ++i) {
        double ui = (1 - std::cos(kPiD * gl.x[i])) / 2, wi = gl.w[i] * kPiD / 2 * std::sin(kPiD * gl.x[i]);
        for (int j = 0; j < 48; ++j) {
            double uj = (1 - std::cos(kPiD * gl.x[j])) / 2,
                   wj = gl.w[j] * kPiD / 2 * std::sin(kPiD * gl.x[j]);
            SurfacePoint sp = surface_at(sample_object({float(ui), float(uj)}));
            sum += wi * wj * area_scale(sp.n);
        }
    }
    area_ = float(object_area() * sum);
}

Vec3d AnalyticShape::to_object(Point3f p) const {
    const Matrix4& a = world_from_object_.inverse_matrix();
    double x = p.x, y = p.y, z = p.z;
    return {a(0, 0) * x + a(0, 1) * y + a(0, 2) * z + a(0, 3),
            a(1, 0) * x + a(1, 1) * y + a(1, 2) * z + a(1, 3),
            a(2, 0) * x + a(2, 1) * y + a(2, 2) * z + a(2, 3)};
}

Vec3d AnalyticShape::to_object(Vector3f v) const {
    const Matrix4& a = world_from_object_.inverse_matrix();
    double x = v.x, y = v.y, z = v.z;
    return {a(0, 0) * x + a(0, 1) * y + a(0, 2) * z, a(1, 0) * x + a(1, 1) * y + a(1, 2) * z,
            a(2, 0) * x + a(2, 1) * y + a(2, 2) * z};
}

Point3f AnalyticShape::to_world(Vec3d p, Vector3f* p_error) const {
    const Matrix4& m = world_from_object_.matrix();
    Point3f pw;
    for (int r = 0; r < 3; ++r) {
        double v = m(r, 0) * p.x + m(r, 1) * p.y + m(r, 2) * p.z + m(r, 3);
        double mag =
            std::abs(m(r, 0) * p.x) + std::abs(m(r, 1) * p.y) + std::abs(m(r, 2) * p.z) + std::abs(m(r, 3));
        pw[r] = float(v);
        // The object point is on the surface to double precision and the product is formed in double;
        // rounding to float adds half an ulp. γ2 of the magnitudes bounds all three with a wide margin.
        (*p_error)[r] = float(gamma_bound(2) * (mag + std::abs(v)));
    }
    return pw;
}

Vector3f AnalyticShape::to_world(Vec3d v) const {
    const Matrix4& m = world_from_object_.matrix();
    return {float(m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z),
            float(m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z),
            float(m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z)};
}

Normal3f AnalyticShape::world_normal(Vec3d n) const {
    const Matrix4& a = world_from_object_.inverse_matrix(); // normals turn with M^-T
    Vec3d w{a(0, 0) * n.x + a(1, 0) * n.y + a(2, 0) * n.z, a(0, 1) * n.x + a(1, 1) * n.y + a(2, 1) * n.z,
            a(0, 2) * n.x + a(1, 2) * n.y + a(2, 2) * n.z};
    double inv = (flip_ ? -1 : 1) / length(w);
    return {float(w.x * inv), float(w.y * inv), float(w.z * inv)};
}

Normal3f AnalyticShape::world_normal_derivative(Vec3d n) const {
    const Matrix4& a = world_from_object_.inverse_matrix(); // as normals: by M^-T
    return {float(a(0, 0) * n.x + a(1, 0) * n.y + a(2, 0) * n.z),
            float(a(0, 1) * n.x + a(1, 1) * n.y + a(2, 1) * n.z),
            float(a(0, 2) * n.x + a(1, 2) * n.y + a(2, 2) * n.z)};
}

double AnalyticShape::area_scale(Vec3d n) const {
    if (similarity_) return scale_ * scale_;
    const Matrix4& a = world_from_object_.inverse_matrix();
    Vec3d w{a(0, 0) * n.x + a(1, 0) * n.y + a(2, 0) * n.z, a(0, 1) * n.x + a(1, 1) * n.y + a(2, 1) * n.z,
            a(0, 2) * n.x + a(1, 2) * n.y + a(2, 2) * n.z};
    return std::abs(det_) * length(w);
}

Bounds3f AnalyticShape::bounds() const {
    Bounds3f ob = object_bounds(), b;
    for (float x : {ob.lo.x, ob.hi.x})
        for (float y : {ob.lo.y, ob.hi.y})
            for (float z : {ob.lo.z, ob.hi.z}) {
                Vector3f err;
                Point3f p = to_world(Vec3d{x, y, z}, &err);
                b.extend(p - err);
                b.extend(p + err);
            }
    return b;
}

// The slab test of the ray against the culling bounds (PBR 4th ed. §6.1.2): each axis clips the parametric
// interval; a zero direction component gives ±inf (or NaN, which the comparisons leave out), and t_far is
// widened by 1 + 2γ3 against the rounding of the two products.
bool AnalyticShape::misses_bounds(const Ray& ray, float tmin, float tmax) const {
    float t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        float inv = 1 / ray.d[a];
        float t_near = (cull_.lo[a] - ray.o[a]) * inv, t_far = (cull_.hi[a] - ray.o[a]) * inv;
        if (t_near > t_far) std::swap(t_near, t_far);
        t_far *= 1 + 2 * float(gamma_bound(3));
        t0 = t_near > t0 ? t_near : t0;
        t1 = t_far < t1 ? t_far : t1;
        if (t0 > t1) return true;
    }
    return false;
}

int AnalyticShape::crossings(const Ray& ray, float tmin, float tmax, Crossing out[2]) const {
    // Embree calls a user geometry of one primitive for every ray it traces (the primitive's BVH is a
    // single leaf, whose box it does not test), so most rays end here, before the double-precision roots.
    if (cull_valid_ && misses_bounds(ray, tmin, tmax)) return 0;
    double t[2];
    int n = world_roots(ray, t), count = 0;
    if (n >= 0) {
        for (int i = 0; i < n; ++i)
            if (t[i] > tmin && t[i] < tmax) out[count++] = {t[i], Vec3d{}, i};
        return count;
    }
    Vec3d o = to_object(ray.o), d = to_object(ray.d);
    n = roots(o, d, t);
    for (int i = 0; i < n; ++i) {
        if (!(t[i] > tmin && t[i] < tmax)) continue;
        Vec3d p = o + d * t[i];
        if (!inside_clip(p)) continue;
        out[count++] = {t[i], p, i};
    }
    return count;
}

void AnalyticShape::fill_hit(float t, const Ray& ray, SurfaceHit* hit) const {
    SurfacePoint sp = surface_at(to_object(ray.o) + to_object(ray.d) * t);
    hit->p = to_world(sp.p, &hit->p_error);
    hit->t = t;
    hit->wo = normalize(-ray.d);
    hit->n = world_normal(sp.n);
    hit->ns = hit->n;
    hit->uv = sp.uv;
    hit->dpdu = to_world(sp.dpdu);
    hit->partials_source = this;
    hit->local = {float(sp.p.x), float(sp.p.y), float(sp.p.z)};
}

ShadingPartials AnalyticShape::shading_partials(std::uint32_t, Point3f local) const {
    SurfacePoint sp = surface_at(Vec3d{local.x, local.y, local.z});
    SecondPartials d = partials_at(sp);
    Vector3f dpdu = to_world(sp.dpdu), dpdv = to_world(d.dpdv);
    return {dpdu, dpdv, world_normal_derivative(d.dndu), world_normal_derivative(d.dndv), dpdu, dpdv};
}

SurfaceHit AnalyticShape::alpha_point(const Crossing& c) const {
    SurfacePoint sp = surface_at(c.p);
    SurfaceHit h;
    h.p = to_world(sp.p, &h.p_error);
    h.n = h.ns = world_normal(sp.n);
    h.uv = sp.uv;
    h.dpdu = to_world(sp.dpdu);
    return h;
}

ShapePoint AnalyticShape::world_sample(Vec3d p) const {
    SurfacePoint sp = surface_at(p);
    ShapePoint s;
    s.p = to_world(sp.p, &s.p_error);
    s.n = world_normal(sp.n);
    s.uv = sp.uv;
    return s;
}

AreaShapeSample AnalyticShape::sample_area(Point2f u) const {
    Vec3d p = sample_object(u);
    // p_A = 1 / A for a similarity, 1 / (A_obj J(n)) point by point otherwise (see analytic_shape.h).
    AreaPdf pdf(similarity_ ? 1 / area_ : float(1 / (object_area() * area_scale(surface_at(p).n))));
    return {world_sample(p), pdf};
}

AreaPdf AnalyticShape::area_pdf(Point3f p) const {
    if (similarity_) return AreaPdf(1 / area_);
    return AreaPdf(float(1 / (object_area() * area_scale(surface_at(to_object(p)).n))));
}

SolidAnglePdf AnalyticShape::pdf(const ShapeSampleContext& ctx, Vector3f wi, Point3f p_hit,
                                 Normal3f n_hit) const {
    return area_pdf_to_solid_angle(area_pdf(p_hit), ctx.p, p_hit, n_hit, wi);
}

} // namespace illum
