#include "illum/light/moving_area_light.h"

#include <algorithm>
#include <cmath>

#include "illum/geometry/ray.h"

namespace illum {

namespace {

// The error bound of m(p) for a point p known to within err (after PBR 4th ed. §6.8.6): each coordinate gets
// |M| (γ3 |p| + (1 + γ3) err) + γ3 |translation|. A further 2⁻¹⁸ of the point's magnitude covers the
// difference between R(t) · M0 applied in two steps here and W(t) applied in one by the accelerator (float
// matrices from Embree's interpolation): the ends of shadow rays keep clear of the moving surface.
Vector3f mapped_error(const Transform& t, Point3f p, Vector3f err) {
    const Matrix4& m = t.matrix();
    Vector3f out;
    double magnitude = 0;
    for (int r = 0; r < 3; ++r) {
        double e = gamma_bound(3) * std::abs(m(r, 3));
        double q = m(r, 3);
        for (int c = 0; c < 3; ++c) {
            e += std::abs(m(r, c)) * (gamma_bound(3) * std::abs(p[c]) + (1 + gamma_bound(3)) * err[c]);
            q += m(r, c) * p[c];
        }
        out[r] = float(e);
        magnitude = std::max({magnitude, std::abs(q), std::abs(m(r, 3))});
    }
    float margin = float(magnitude * 0x1p-18);
    return out + Vector3f{margin, margin, margin};
}

Normal3f mapped_normal(const Transform& t, Normal3f n) {
    if (n == Normal3f{}) return n;
    return normalize(t(n));
}

// The 3x3 part's determinant.
double linear_det(const Transform& t) {
    const Matrix4& m = t.matrix();
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
           m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

// How R scales area on a surface of unit normal n0 at the start pose (Nanson's formula, n da = det A A⁻ᵀ N
// dA): da / dA = |det A| |A⁻ᵀ n0|. 1 for a rigid R.
double area_scale(const Transform& r, Normal3f n0) {
    return std::abs(linear_det(r)) * double(length(Vector3f(r(n0))));
}

// How R scales solid angle about a unit direction w0 (the map w ↦ A w / |A w|): dω / dω0 = |det A| / |A w0|³.
double solid_angle_scale(const Transform& r, Vector3f w0) {
    double l = length(r(w0));
    return std::abs(linear_det(r)) / (l * l * l);
}

// The hit as the still light sees it: its point and normal at the start pose.
SurfaceHit at_start(const Transform& start_from_world, const SurfaceHit& hit) {
    SurfaceHit h = hit;
    h.p = start_from_world(hit.p);
    h.p_error = mapped_error(start_from_world, hit.p, hit.p_error);
    h.n = mapped_normal(start_from_world, hit.n);
    h.ns = mapped_normal(start_from_world, hit.ns);
    return h;
}

// A density per steradian at the start pose (receiver q0, light point p0 of normal n0) as one at the world's
// pose (q, p, n): per unit area at p0 it is p_ω0 |cos θ0| / |p0 - q0|², per unit area at p that divided by
// the area scale, and per steradian at q that times |p - q|² / |cos θ| (PBR 4th ed. §4.2.3).
float world_solid_angle_pdf(float pdf0, const Transform& r, Point3f q0, Point3f p0, Normal3f n0, Point3f q,
                            Point3f p, Normal3f n) {
    Vector3f d0 = p0 - q0, d = p - q;
    double l0 = length_squared(d0), l = length_squared(d);
    if (!(l0 > 0) || !(l > 0)) return 0;
    double cos0 = std::abs(dot(Vector3f(n0), d0)) / std::sqrt(l0),
           cos = std::abs(dot(Vector3f(n), d)) / std::sqrt(l);
    if (!(cos > 0)) return 0;
    double pdf_area = pdf0 * cos0 / l0 / area_scale(r, n0);
    return float(pdf_area * l / cos);
}

} // namespace

std::optional<Transform> MovingAreaLight::relative_motion(float time) const {
    if (!accelerator_ || instance_ == Accelerator::kNoInstance) return std::nullopt;
    std::optional<Transform> w = accelerator_->moving_transform(instance_, time);
    if (!w) return std::nullopt;
    return *w * object_from_start_;
}

std::optional<LightLiSample> MovingAreaLight::sample_li(const LightSampleContext& ctx, Point2f u,
                                                        const SampledWavelengths& lambda) const {
    std::optional<Transform> r = relative_motion(ctx.time);
    if (!r) return std::nullopt;
    Transform start_from_world = r->inverse();
    LightSampleContext at0(start_from_world(ctx.p), mapped_error(start_from_world, ctx.p, ctx.p_error),
                           mapped_normal(start_from_world, ctx.n), ctx.time);
    std::optional<LightLiSample> s = still_->sample_li(at0, u, lambda);
    if (!s) return std::nullopt;
    // Back to the world at ctx.time, with the density carried over (unchanged by a rigid R(t)).
    Point3f p = (*r)(s->p_light);
    Normal3f n = mapped_normal(*r, s->n_light);
    Vector3f d = p - ctx.p;
    float d2 = length_squared(d);
    if (!(d2 > 0)) return std::nullopt;
    SolidAnglePdf pdf(world_solid_angle_pdf(s->pdf.value, *r, at0.p, s->p_light, s->n_light, ctx.p, p, n));
    if (!(pdf > SolidAnglePdf(0))) return std::nullopt;
    s->wi = d / std::sqrt(d2);
    s->p_light_error = mapped_error(*r, s->p_light, s->p_light_error);
    s->p_light = p;
    s->n_light = n;
    s->pdf = pdf;
    s->biradiance = biradiance(s->radiance, pdf);
    return s;
}

SolidAnglePdf MovingAreaLight::pdf_li(const LightSampleContext& ctx, Vector3f wi,
                                      const SurfaceHit* hit) const {
    if (!hit) return SolidAnglePdf(0);
    std::optional<Transform> r = relative_motion(hit->time);
    if (!r) return SolidAnglePdf(0);
    Transform start_from_world = r->inverse();
    LightSampleContext at0(start_from_world(ctx.p), mapped_error(start_from_world, ctx.p, ctx.p_error),
                           mapped_normal(start_from_world, ctx.n), hit->time);
    SurfaceHit h0 = at_start(start_from_world, *hit);
    Vector3f w0 = start_from_world(wi);
    float len = length(w0);
    if (!(len > 0)) return SolidAnglePdf(0);
    SolidAnglePdf pdf0 = still_->pdf_li(at0, w0 / len, &h0);
    if (!(pdf0 > SolidAnglePdf(0))) return SolidAnglePdf(0);
    return SolidAnglePdf(world_solid_angle_pdf(pdf0.value, *r, at0.p, h0.p, h0.n, ctx.p, hit->p, hit->n));
}

Radiance3 MovingAreaLight::radiance(const SurfaceHit& hit, Vector3f w,
                                    const SampledWavelengths& lambda) const {
    std::optional<Transform> r = relative_motion(hit.time);
    if (!r) return {};
    Transform start_from_world = r->inverse();
    return still_->radiance(at_start(start_from_world, hit), start_from_world(w), lambda);
}

AreaPdf MovingAreaLight::pdf_le_position(const SurfaceHit& hit) const {
    std::optional<Transform> r = relative_motion(hit.time);
    if (!r) return AreaPdf(0);
    SurfaceHit h0 = at_start(r->inverse(), hit);
    return AreaPdf(float(still_->pdf_le_position(h0).value / area_scale(*r, h0.n)));
}

// The photon of the still light, carried to the world at `time`: its density per unit area divided by the
// area scale, per steradian by the solid-angle scale of its direction (both 1 for a rigid R(t)); the
// radiance is the same (A w and A⁻ᵀ n keep the sign of w · n), so flux = L |cos θ| / (p_pos p_dir) in the
// world's terms.
std::optional<LightLeSample> MovingAreaLight::sample_le_at(float time, Point2f u1, Point2f u2,
                                                           const SampledWavelengths& lambda) const {
    std::optional<Transform> r = relative_motion(time);
    if (!r) return std::nullopt;
    std::optional<LightLeSample> s = still_->sample_le(u1, u2, lambda);
    if (!s) return std::nullopt;
    Vector3f d = (*r)(s->ray.d);
    float len = length(d);
    if (!(len > 0)) return std::nullopt;
    d = d / len;
    Normal3f n = mapped_normal(*r, s->n);
    float cos_theta = std::abs(dot(Vector3f(n), d));
    AreaPdf pdf_pos(float(s->pdf_pos.value / area_scale(*r, s->n)));
    SolidAnglePdf pdf_dir(float(s->pdf_dir.value / solid_angle_scale(*r, s->ray.d)));
    if (!(pdf_pos > AreaPdf(0)) || !(pdf_dir > SolidAnglePdf(0)) || !(cos_theta > 0)) return std::nullopt;
    Vector3f err = mapped_error(*r, s->p_surface, s->p_error);
    Point3f p = (*r)(s->p_surface);
    // The origin off the surface towards the photon's side, by the error bound in the world.
    s->ray = Ray{offset_ray_origin(p, err, n, d), d, kInfinity, time};
    s->n = n;
    s->p_surface = p;
    s->p_error = err;
    s->pdf_pos = pdf_pos;
    s->pdf_dir = pdf_dir;
    s->flux = s->radiance * cos_theta / pdf_pos / pdf_dir;
    return s;
}

void MovingAreaLight::pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const {
    *pos = AreaPdf(0);
    *dir = SolidAnglePdf(0);
    std::optional<Transform> r = relative_motion(ray.time);
    if (!r) return;
    Transform start_from_world = r->inverse();
    Ray r0 = ray;
    r0.o = start_from_world(ray.o);
    Vector3f w0 = start_from_world(ray.d);
    float len = length(w0);
    if (!(len > 0)) return;
    r0.d = w0 / len;
    Normal3f n0 = mapped_normal(start_from_world, n);
    still_->pdf_le(r0, n0, pos, dir);
    if (n0 != Normal3f{}) *pos = AreaPdf(float(pos->value / area_scale(*r, n0)));
    *dir = SolidAnglePdf(float(dir->value / solid_angle_scale(*r, r0.d)));
}

} // namespace illum
