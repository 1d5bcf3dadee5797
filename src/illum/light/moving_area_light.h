// A moving area light (a shape with an "AreaLightSource" under "ActiveTransform"/"TransformTimes" motion,
// which pbrt-v4 rejects): the emitter's shape as it stands at the start of its motion, M0 = the start
// world_from_object, carried at time t by the relative motion
//   R(t) = W(t) · M0⁻¹,
// W(t) being the transform the accelerator traces the moving shape with at t (Accelerator::moving_transform),
// so every point sampled on the light lies on the surface rays find then. Each query maps its points,
// normals and directions to the start pose by R(t)⁻¹, asks the still light there and maps the answer back by
// R(t) (the time: the receiver's, the hit's or the photon ray's).
//
// R(t) is affine, A its linear part. Radiance is carried unchanged (A w and A⁻ᵀ n keep the sign of w · n);
// densities are carried by the Jacobians of the maps (1 for a rigid R(t): a motion that keeps its scale):
// per unit area divided by |det A| |A⁻ᵀ n0| (Nanson's formula, n0 the unit normal at the start pose), per
// steradian of a photon's direction w0 divided by |det A| / |A w0|³, and per steradian at a receiver through
// the density per unit area (p_A = p_ω |cos θ| / r²). So a motion that changes the light's size is exact
// too; only power(), which picks lights for sampling, stays that of the start pose.
#pragma once

#include <memory>

#include "illum/geometry/accelerator.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/light/light.h"

namespace illum {

class MovingAreaLight final : public Light {
public:
    // still: the light on the start-pose shape (world_from_object = start_from_object at `start_time`).
    MovingAreaLight(std::unique_ptr<DiffuseAreaLight> still, const Transform& start_from_object,
                    float start_time)
        : Light(LightType::Area), still_(std::move(still)), object_from_start_(start_from_object.inverse()),
          start_time_(start_time) {}
    // The moving instance that traces the shape (set once it is placed).
    void set_motion(const Accelerator* accelerator, std::uint32_t instance) {
        accelerator_ = accelerator;
        instance_ = instance;
    }
    const DiffuseAreaLight& still() const { return *still_; }

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const override;
    Radiance3 radiance(const SurfaceHit& hit, Vector3f w, const SampledWavelengths& lambda) const override;
    Power3 power() const override { return still_->power(); }
    AreaPdf pdf_le_position(const SurfaceHit& hit) const override;
    // At the start of the motion (the still light's own emission).
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override {
        return sample_le_at(start_time_, u1, u2, lambda);
    }
    std::optional<LightLeSample> sample_le_at(float time, Point2f u1, Point2f u2,
                                              const SampledWavelengths& lambda) const override;
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    // R(t) (the start pose to the world at t); nullopt where the motion is singular or not yet placed.
    std::optional<Transform> relative_motion(float time) const;

private:
    std::unique_ptr<DiffuseAreaLight> still_;
    Transform object_from_start_; // M0⁻¹
    float start_time_;
    const Accelerator* accelerator_ = nullptr;
    std::uint32_t instance_ = Accelerator::kNoInstance;
};

} // namespace illum
