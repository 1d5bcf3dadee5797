// A spot light: a point source of intensity I inside a cone about its axis, with pbrt-v4's smooth
// falloff: I(θ) = I · smoothstep(cos θ; cos θ_end, cos θ_start), where θ_end is the cone angle and
// θ_start = θ_end - δ (the cone delta). Smoothstep s(t) = 3t² - 2t³ integrates to 1/2 over [0, 1], so the
// power is exactly Φ = 2π I [(1 - cos θ_start) + (cos θ_start - cos θ_end) / 2].
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "illum/light/light.h"
#include "illum/light/point_source.h"
#include "illum/math/frame.h"
#include "illum/math/warp.h"
#include "illum/radiometry/emission.h"

namespace illum {

class SpotLight final : public Light {
public:
    // axis: unit direction the light points to; angles in radians (0 < start <= end <= π).
    SpotLight(Point3f position, Vector3f axis, Emission intensity, float cone_angle, float cone_delta)
        : Light(LightType::DeltaPosition), position_(position), frame_(Frame::from_z(axis)),
          intensity_(std::move(intensity)) {
        cone_angle = std::clamp(cone_angle, 1e-6f, kPi);
        float start = std::clamp(cone_angle - cone_delta, 0.0f, cone_angle);
        cos_end_ = std::cos(cone_angle);
        cos_start_ = std::cos(start);
        cos_clip_ = std::cos(std::min(cone_angle + 1e-3f, kPi));
    }

    // The falloff factor in [0, 1] for a direction cos θ from the axis.
    float falloff(float cos_theta) const {
        if (cos_theta >= cos_start_) return 1;
        if (cos_theta <= cos_end_) return 0;
        float t = (cos_theta - cos_end_) / (cos_start_ - cos_end_);
        return t * t * (3 - 2 * t);
    }
    Intensity3 intensity(Vector3f w_world, const SampledWavelengths& lambda) const {
        float f = falloff(dot(w_world, frame_.n));
        if (f == 0) return {}; // outside the cone: the spectrum is not looked up
        return Intensity3(intensity_.at(lambda)) * f;
    }

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f,
                                           const SampledWavelengths& lambda) const override {
        return point_source_li(position_, ctx.p, [&](Vector3f w) { return intensity(w, lambda); });
    }
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(0);
    }
    std::optional<Point3f> position() const override { return position_; }
    // The line's stretch inside the cone θ <= θ_end (widened by 1e-3 rad against rounding): with
    // w = m + t d, m = o - c, the cone is (w·a)² >= cos² |w|² on the nappe w·a >= 0, a quadratic
    // A t² + 2 B t + C >= 0 and a half-line. A cone of at most 90° is convex, so the stretch is one interval.
    bool illuminated_interval(Point3f o, Vector3f d, float* t0, float* t1) const override {
        if (cos_clip_ <= 0) return true; // wider than a half-space: not convex, not narrowed
        Vector3f m = o - position_;
        const Vector3f& a = frame_.n;
        double ma = dot(m, a), da = dot(d, a), c2 = double(cos_clip_) * cos_clip_;
        double qa = da * da - c2 * dot(d, d), qb = ma * da - c2 * dot(m, d), qc = ma * ma - c2 * dot(m, m);
        // The nappe's half-line: ma + t da >= 0.
        double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
        if (da > 0)
            lo = -ma / da;
        else if (da < 0)
            hi = -ma / da;
        else if (ma < 0)
            return false;
        // Where the quadratic is >= 0, intersected with the half-line.
        double disc = qb * qb - qa * qc;
        if (qa < 0) {
            if (disc < 0) return false;
            double r = std::sqrt(disc), q = -(qb + std::copysign(r, qb));
            double ra = q / qa, rb = q != 0 ? qc / q : ra;
            lo = std::max(lo, std::min(ra, rb));
            hi = std::min(hi, std::max(ra, rb));
        } else if (qa > 0 && disc > 0) {
            // Outside the roots: the half-line keeps the part on this nappe's side.
            double r = std::sqrt(disc), q = -(qb + std::copysign(r, qb));
            double ra = q / qa, rb = q != 0 ? qc / q : ra;
            double r0 = std::min(ra, rb), r1 = std::max(ra, rb);
            // The half-line contains one of (-inf, r0] and [r1, inf) (a ray along the cone's line, both).
            if (hi <= r1)
                hi = std::min(hi, r0);
            else
                lo = std::max(lo, r1);
        } else if (qa == 0 && qb != 0) {
            // Parallel to the cone's surface: the linear 2 B t + C >= 0.
            double r = -qc / (2 * qb);
            if (qb > 0)
                lo = std::max(lo, r);
            else
                hi = std::min(hi, r);
        } else if (qa == 0 && qc < 0) {
            return false;
        }
        double a0 = std::max(lo, double(*t0)), a1 = std::min(hi, double(*t1));
        if (!(a1 > a0)) return false;
        *t0 = float(a0);
        *t1 = float(a1);
        return true;
    }
    Power3 power() const override {
        return Intensity3(intensity_.rgb_value()) *
               SolidAngle(2 * kPi * ((1 - cos_start_) + (cos_start_ - cos_end_) / 2));
    }
    // Emitting about the axis: θo = θ_start (full intensity), θe = θ_end - θ_start (the falloff), phi = 4π I
    // with I the peak intensity. (A hard-edged cone has θe = 0, whose cosine 1 no direction can exceed:
    // it is kept just below, as pbrt-v4 does, PBR 4th ed. §12.6.3.)
    std::optional<LightBounds> bounds() const override {
        LightBounds b = point_bounds(position_, 4 * kPi * intensity_.rgb.luminance());
        b.w = frame_.n;
        b.cos_theta_o = cos_start_;
        b.cos_theta_e = std::min(std::cos(safe_acos(cos_end_) - safe_acos(cos_start_)), 0.999f);
        return b;
    }
    // Uniform within the cone θ <= θ_end: flux = I(θ) / p_dir.
    std::optional<LightLeSample> sample_le(Point2f, Point2f u2,
                                           const SampledWavelengths& lambda) const override {
        Vector3f w = frame_.to_world(sample_uniform_cone(u2, cos_end_));
        SolidAnglePdf pdf_dir(uniform_cone_pdf(cos_end_));
        Intensity3 i = intensity(w, lambda);
        return LightLeSample{Ray{position_, w}, {}, {}, AreaPdf(1), pdf_dir, i / pdf_dir, position_, {}};
    }
    void pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const override {
        *pos = AreaPdf(1);
        float cos_theta = dot(ray.d, frame_.n) / length(ray.d);
        *dir = SolidAnglePdf(cos_theta >= cos_end_ ? uniform_cone_pdf(cos_end_) : 0.0f);
    }
    Vector3f axis() const { return frame_.n; }
    float cos_start() const { return cos_start_; }
    float cos_end() const { return cos_end_; }

private:
    Point3f position_;
    Frame frame_;
    Emission intensity_;
    float cos_start_ = 1, cos_end_ = 0;
    float cos_clip_ = 0; // the cone, slightly widened, that illuminated_interval() clips to
};

} // namespace illum
