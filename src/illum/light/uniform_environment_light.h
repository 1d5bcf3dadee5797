// A constant environment: radiance L arrives from every direction. Sampled uniformly over the sphere.
#pragma once

#include "illum/light/light.h"
#include "illum/math/warp.h"
#include "illum/radiometry/emission.h"

namespace illum {

class UniformEnvironmentLight final : public Light {
public:
    explicit UniformEnvironmentLight(Emission radiance)
        : Light(LightType::Infinite), radiance_(std::move(radiance)) {}

    void preprocess(const Bounds3f& scene_bounds) override {
        scene_bounds.bounding_sphere(&scene_center_, &scene_radius_);
    }
    std::optional<LightLiSample> sample_li(const LightSampleContext&, Point2f u,
                                           const SampledWavelengths& lambda) const override {
        Vector3f wi = sample_uniform_sphere(u);
        SolidAnglePdf pdf(uniform_sphere_pdf());
        Radiance3 l(radiance_.at(lambda));
        return LightLiSample{wi, l, biradiance(l, pdf), pdf, {}, {}, {}, true};
    }
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(uniform_sphere_pdf());
    }
    Radiance3 le(const Ray&, const SampledWavelengths& lambda) const override {
        return Radiance3(radiance_.at(lambda));
    }
    // The power that crosses a disk of the scene's radius from all directions: Φ = L G with the étendue
    // G = 4π · π r² of the disk and the sphere of directions.
    Power3 power() const override {
        return Radiance3(radiance_.rgb_value()) * Etendue(4 * kPi * kPi * scene_radius_ * scene_radius_);
    }

    // A uniform direction, then a point on the disk of the scene's radius perpendicular to it, outside
    // the scene: flux = L / (p_pos p_dir) = 4π · π r² · L on average (exactly, for a constant map).
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override {
        if (!(scene_radius_ > 0)) return std::nullopt;
        Vector3f wi = sample_uniform_sphere(u2); // towards the environment
        SolidAnglePdf pdf_dir(uniform_sphere_pdf());
        return emit_from_disk(wi, u1, Radiance3(radiance_.at(lambda)), pdf_dir);
    }

    void pdf_le(const Ray&, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const override {
        *pos = disk_emission_pdf(scene_radius_);
        *dir = SolidAnglePdf(uniform_sphere_pdf());
    }

    // The photon for incident direction wi (towards the environment) of radiance l: it starts on the
    // disk of radius r centred at c + r wi, perpendicular to wi, and travels along -wi.
    LightLeSample emit_from_disk(Vector3f wi, Point2f u1, Radiance3 l, SolidAnglePdf pdf_dir) const {
        return disk_emission(scene_center_, scene_radius_, wi, u1, l, pdf_dir);
    }

private:
    Emission radiance_;
    Point3f scene_center_;
    float scene_radius_ = 0;
};

} // namespace illum
