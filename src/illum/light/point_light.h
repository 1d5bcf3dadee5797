// An isotropic point source of intensity I [W/sr]: it delivers biradiance I / r² (total power 4π I).
#pragma once

#include "illum/light/light.h"
#include "illum/math/warp.h"
#include "illum/radiometry/emission.h"

namespace illum {

class PointLight final : public Light {
public:
    PointLight(Point3f position, Emission intensity)
        : Light(LightType::DeltaPosition), position_(position), intensity_(std::move(intensity)) {}

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f,
                                           const SampledWavelengths& lambda) const override {
        Vector3f d = position_ - ctx.p;
        float d2 = length_squared(d);
        if (d2 == 0) return std::nullopt;
        return LightLiSample{d / std::sqrt(d2),
                             {},
                             biradiance(intensity(lambda), d2),
                             SolidAnglePdf(1),
                             position_,
                             {},
                             {},
                             false};
    }
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(0);
    }
    // Φ = ∫ I dω = 4π I.
    std::optional<Point3f> position() const override { return position_; }
    Power3 power() const override { return Intensity3(intensity_.rgb_value()) * SolidAngle(4 * kPi); }
    // A point emitting every way: θo = π, θe = π/2, phi = 4π I.
    std::optional<LightBounds> bounds() const override {
        return point_bounds(position_, power().rgb().luminance());
    }
    // Uniform over the sphere of directions: flux = I / (1/4π) = 4π I for every photon.
    std::optional<LightLeSample> sample_le(Point2f, Point2f u2,
                                           const SampledWavelengths& lambda) const override {
        SolidAnglePdf pdf_dir(uniform_sphere_pdf());
        return LightLeSample{Ray{position_, sample_uniform_sphere(u2)},
                             {},
                             {},
                             AreaPdf(1),
                             pdf_dir,
                             intensity(lambda) / pdf_dir,
                             position_,
                             {}};
    }
    void pdf_le(const Ray&, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const override {
        *pos = AreaPdf(1);
        *dir = SolidAnglePdf(uniform_sphere_pdf());
    }
    Intensity3 intensity(const SampledWavelengths& lambda) const { return Intensity3(intensity_.at(lambda)); }

private:
    Point3f position_;
    Emission intensity_;
};

} // namespace illum
