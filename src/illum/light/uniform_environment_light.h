// A constant environment: radiance L arrives from every direction. Sampled uniformly over the sphere.
#pragma once

#include "illum/light/light.h"
#include "illum/math/warp.h"

namespace illum {

class UniformEnvironmentLight final : public Light {
public:
    explicit UniformEnvironmentLight(Radiance3 radiance) : Light(LightType::Infinite), radiance_(radiance) {}

    void preprocess(const Bounds3f& scene_bounds) override {
        Point3f c;
        scene_bounds.bounding_sphere(&c, &scene_radius_);
    }
    std::optional<LightLiSample> sample_li(const LightSampleContext&, Point2f u) const override {
        Vector3f wi = sample_uniform_sphere(u);
        SolidAnglePdf pdf(uniform_sphere_pdf());
        return LightLiSample{wi, radiance_, biradiance(radiance_, pdf), pdf, {}, {}, {}, true};
    }
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(uniform_sphere_pdf());
    }
    Radiance3 le(const Ray&) const override { return radiance_; }
    // The power that crosses a disk of the scene's radius from all directions: 4π · π r² · L.
    Power3 power() const override {
        return Power3(radiance_.rgb * (4 * kPi * kPi * scene_radius_ * scene_radius_));
    }

private:
    Radiance3 radiance_;
    float scene_radius_ = 0;
};

} // namespace illum
