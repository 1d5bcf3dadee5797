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

// The hit as the still light sees it: its point and normal at the start pose.
SurfaceHit at_start(const Transform& start_from_world, const SurfaceHit& hit) {
    SurfaceHit h = hit;
    h.p = start_from_world(hit.p);
    h.p_error = mapped_error(start_from_world, hit.p, hit.p_error);
    h.n = mapped_normal(start_from_world, hit.n);
    h.ns = mapped_normal(start_from_world, hit.ns);
    return h;
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
    // Back to the world at ctx.time; a rigid R(t) keeps the solid-angle density and the radiance.
    Point3f p = (*r)(s->p_light);
    Vector3f d = p - ctx.p;
    float d2 = length_squared(d);
    if (!(d2 > 0)) return std::nullopt;
    s->wi = d / std::sqrt(d2);
    s->p_light_error = mapped_error(*r, s->p_light, s->p_light_error);
    s->p_light = p;
    s->n_light = mapped_normal(*r, s->n_light);
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
    return still_->pdf_li(at0, w0 / len, &h0);
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
    return still_->pdf_le_position(at_start(r->inverse(), hit));
}

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
    Vector3f err = mapped_error(*r, s->p_surface, s->p_error);
    Point3f p = (*r)(s->p_surface);
    // The origin off the surface towards the photon's side, by the error bound in the world.
    s->ray = Ray{offset_ray_origin(p, err, n, d), d, kInfinity, time};
    s->n = n;
    s->p_surface = p;
    s->p_error = err;
    return s;
}

void MovingAreaLight::pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const {
    std::optional<Transform> r = relative_motion(ray.time);
    if (!r) {
        *pos = AreaPdf(0);
        *dir = SolidAnglePdf(0);
        return;
    }
    Transform start_from_world = r->inverse();
    Ray r0 = ray;
    r0.o = start_from_world(ray.o);
    r0.d = start_from_world(ray.d);
    still_->pdf_le(r0, mapped_normal(start_from_world, n), pos, dir);
}

} // namespace illum
