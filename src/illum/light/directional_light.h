// A directional (distant) light: parallel light from direction w (towards the light) that delivers
// irradiance E to a surface perpendicular to it. Its "power" is what crosses the disk of the scene's
// bounding sphere: Φ = E π r².
#pragma once

#include "illum/light/light.h"
#include "illum/math/frame.h"
#include "illum/math/warp.h"
#include "illum/radiometry/emission.h"

namespace illum {

class DirectionalLight final : public Light {
public:
    // w_light: unit direction from the scene towards the light. e: irradiance on a perpendicular surface.
    DirectionalLight(Vector3f w_light, Emission e)
        : Light(LightType::DeltaDirection), w_(w_light), e_(std::move(e)) {}

    void preprocess(const Bounds3f& scene_bounds) override {
        scene_bounds.bounding_sphere(&center_, &radius_);
    }

    std::optional<LightLiSample> sample_li(const LightSampleContext&, Point2f,
                                           const SampledWavelengths& lambda) const override {
        // The struct's biradiance is the irradiance on a perpendicular surface (see light.h).
        return LightLiSample{w_, {}, biradiance(irradiance(lambda)), SolidAnglePdf(1), {}, {}, {}, true};
    }
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(0);
    }
    Power3 power() const override { return Irradiance3(e_.rgb_value()) * Area(kPi * radius_ * radius_); }
    // A point uniform on the disk of the scene's radius outside the scene, perpendicular to w; the
    // direction is the delta -w (pdf_dir = 1 as a probability): flux = E / p_pos = E π r².
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f,
                                           const SampledWavelengths& lambda) const override {
        if (!(radius_ > 0)) return std::nullopt;
        Frame f = Frame::from_z(w_);
        Point2f d = sample_uniform_disk_concentric(u1);
        Point3f o = center_ + w_ * radius_ + (f.s * d.x + f.t * d.y) * radius_;
        AreaPdf pdf_pos(1 / (kPi * radius_ * radius_));
        return LightLeSample{Ray{o, -w_}, {}, {}, pdf_pos, SolidAnglePdf(1), irradiance(lambda) / pdf_pos,
                             o,           {}};
    }
    // The direction is a delta: probability 1 for a ray along -w (to float rounding), 0 otherwise.
    void pdf_le(const Ray& ray, Normal3f, AreaPdf* pos, SolidAnglePdf* dir) const override {
        *pos = disk_emission_pdf(radius_);
        *dir = SolidAnglePdf(dot(ray.d, -w_) > (1 - 1e-5f) * length(ray.d) ? 1.0f : 0.0f);
    }
    Vector3f direction() const { return w_; }
    Irradiance3 irradiance(const SampledWavelengths& lambda) const { return Irradiance3(e_.at(lambda)); }

private:
    Vector3f w_;
    Emission e_;
    Point3f center_;
    float radius_ = 0;
};

} // namespace illum
