// pbrt-v4's image infinite light with a "portal" (PortalImageInfiniteLight; Bitterli, Novák and Jarosz,
// "Portal-Masked Environment Map Sampling", EGSR 2015): an environment seen only through a rectangular
// window, as from inside a room lit through its one opening.
//
// The portal's frame: x along p3 - p0, y along p1 - p0, z = x × y (pbrt-v4's Frame::FromXY); the environment
// is resampled over the half of the sphere on +z in the "rectified" parameterisation
//   (u, v) = (α + π/2, β + π/2) / π,   α = atan2(w_x, w_z), β = atan2(w_y, w_z)   (w in the portal's frame),
// in which the portal seen from any point p is the axis-aligned rectangle between the (u, v) of its corners
// p0 and p2 (lines of constant α or β are great circles, the portal's edges among them). Its Jacobian is
//   dω / (du dv) = π² (1 - w_x²)(1 - w_y²) / w_z.
// The rectified image is the environment's bilinear lookup at each texel's centre (its resolution that of a
// square input, else about π / the input's mean texel angle); radiance is looked up in it at the nearest
// texel, as pbrt-v4 does, and is zero along any ray that does not pass through the portal:
//   Le(o, ω) = s · L_rect(uv(ω))  if uv(ω) lies within the portal's window seen from o, else 0.
// sample_li draws uv from the texels' L · dω/duv restricted to that window (WindowedDistribution2D), so only
// directions through the portal are sampled.
//
// Photons (sample_le): a direction from the whole rectified distribution and an origin on the scene's disk,
// as for every infinite light (bidirectional MIS in render/path_vertex.cpp takes that disk density for the
// environment's vertex); a photon whose line misses the portal carries nothing (nullopt), one that crosses it
// starts at the crossing point, so it lights only what lies beyond the portal. With the portal inside the
// scene's bounding sphere, E[flux] is then exactly the power through the portal,
//   Φ = s A Σ_t L_t P_t,   P_t = ∫_texel cos θ dω (the texel's projected solid angle, rectified_texel_psa),
// A the portal's area. pbrt-v4's Phi omits the cosine and its photons ignore the portal (they leave the disk
// whatever their line), which adds light to surfaces the portal hides; both are departures for good reason.
#pragma once

#include <array>
#include <string>

#include "illum/envmap/environment_map.h"
#include "illum/image/image.h"
#include "illum/light/light.h"
#include "illum/math/frame.h"
#include "illum/math/transform.h"
#include "illum/math/windowed_distribution.h"

namespace illum {

// Why four points are not a portal (empty when they are one): pbrt-v4's test, opposite edges parallel and
// adjacent edges perpendicular within 10⁻³ of their unit vectors' dot products, and a non-zero area.
std::string portal_shape_problem(const std::array<Point3f, 4>& p);

// The projected solid angle ∫ cos θ dω of the rectified region [α0, α1] x [β0, β1] (angles in [-π/2, π/2]):
// that of the rectangle [tan α0, tan α1] x [tan β0, tan β1] on the plane z = 1, by the corner function of the
// form factor from a point to a parallel rectangle (Howell, "A Catalog of Radiation Heat Transfer
// Configuration Factors", B-3): G(α, β) = ½ [sin α atan2(sin β cos α, cos β) + sin β atan2(sin α cos β, cos
// α)].
double rectified_psa(double alpha0, double alpha1, double beta0, double beta1);

class PortalEnvironmentLight final : public Light {
public:
    // map: the environment in light space, oriented by world_from_light; portal: four world points (valid by
    // portal_shape_problem).
    PortalEnvironmentLight(const EnvironmentMap& map, const Transform& world_from_light, float scale,
                           const std::array<Point3f, 4>& portal);

    void preprocess(const Bounds3f& scene_bounds) override;
    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f u,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext& ctx, Vector3f wi, const SurfaceHit* hit) const override;
    Radiance3 le(const Ray& ray, const SampledWavelengths& lambda) const override;
    // s A Σ L_t P_t: the power through the portal.
    Power3 power() const override { return Power3(SampledSpectrum(power_)); }
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    const Image& rectified() const { return image_; }
    const Frame& frame() const { return frame_; }
    // The rectified coordinates of world direction w and dω/duv there; nullopt behind the portal's plane.
    std::optional<Point2f> image_from_world(Vector3f w, float* jacobian) const;
    // The world direction of rectified coordinates uv and dω/duv there.
    Vector3f world_from_image(Point2f uv, float* jacobian) const;

private:
    // The portal's window in rectified coordinates as seen from p; false when p is not in front of it.
    bool window(Point3f p, Point2f* lo, Point2f* hi) const;
    Radiance3 lookup(Point2f uv, const SampledWavelengths& lambda) const;

    std::array<Point3f, 4> portal_;
    Frame frame_;
    float width_ = 0, height_ = 0; // |p3 - p0|, |p1 - p0|
    Image image_;
    float scale_;
    WindowedDistribution2D distribution_;
    Color3 power_;
    Point3f scene_center_;
    float scene_radius_ = 0;
};

} // namespace illum
