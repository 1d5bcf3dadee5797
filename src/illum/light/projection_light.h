// pbrt-v4's projection light: a point source that projects an image through a perspective frustum, like a
// slide projector. In light space (the CTM at the LightSource; pbrt-v4 flips its y so the image stands
// upright) it looks along +z; the image spans the plane z = 1 over [-sx, sx] x [-sy, sy], with
// tan(fov/2) the half-extent of the image's shorter side (pbrt-v4's screen window with Perspective(fov)).
// The intensity towards ω is the RGB of the texel ω passes through (nearest texel, as pbrt-v4 looks it
// up), an illuminant in spectral mode, times scale:
//   I(ω) = s · L(texel(ω)),   0 outside the frustum.
// A direction through the plane point (a, b) has dω = dA / r³, r = √(1 + a² + b²) (cos θ / r² with cos θ =
// 1 / r), so the exact power is
//   Φ = s Σ_texels L_t Ω_t,   Ω_t = F(a1, b1) - F(a0, b1) - F(a1, b0) + F(a0, b0),  F(a, b) = atan(ab / r),
// the solid angle of an axis-aligned rectangle on the plane z = 1 (the corner formula of the solid angle of
// a rectangle; e.g. Mathar, "Solid angle of a rectangular plate", 2015). pbrt-v4's Phi approximates each Ω_t
// by the texel's plane area times cos³ θ at its centre; its "power" normalisation uses that sum, which the
// light factory reproduces (projection_power_normalisation).
// Photons pick a texel with probability ∝ mean(L_t) Ω_t and a point uniform on it within the plane: the
// density per steradian is p_t / A_t · r³.
#pragma once

#include <vector>

#include "illum/image/image.h"
#include "illum/light/light.h"
#include "illum/math/distribution.h"
#include "illum/math/transform.h"

namespace illum {

// pbrt-v4's projection geometry for an image of w x h texels and a field of view in degrees: the plane
// half-extents sx, sy (the shorter side's is tan(fov / 2)).
struct ProjectionFrustum {
    float sx = 1, sy = 1;
    ProjectionFrustum() = default;
    ProjectionFrustum(int width, int height, float fov_degrees);
    // The texel's rectangle on the plane z = 1 (texel (0, 0) is the image's top left: a = -sx, b = +sy in
    // light space).
    float a(float u) const { return (2 * u - 1) * sx; }
    float b(float v) const { return (1 - 2 * v) * sy; }
};

// pbrt-v4's k_e for "power": the plane area 4 sx sy times the mean over texels of lum(L_t) cos³ θ_t at the
// texel centres; "power" P scales the image by P / k_e.
double projection_power_normalisation(const Image& image, float fov_degrees);
// The exact solid angle of the rectangle [a0, a1] x [b0, b1] on the plane z = 1.
double plane_rectangle_solid_angle(double a0, double a1, double b0, double b1);

class ProjectionLight final : public Light {
public:
    // image: non-negative RGB; scale: s (scale and power already combined).
    ProjectionLight(const Transform& world_from_light, const Image& image, float scale, float fov_degrees);

    Intensity3 intensity(Vector3f w_world, const SampledWavelengths& lambda) const;

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(0);
    }
    std::optional<Point3f> position() const override { return position_; }
    Power3 power() const override { return Power3(SampledSpectrum(power_)); }
    // Emitting along the light's z axis (θo = 0) out to the frustum's corner (θe); phi = 4π times the mean
    // intensity over the frustum's solid angle Ω, Φ / Ω.
    std::optional<LightBounds> bounds() const override;
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

    const ProjectionFrustum& frustum() const { return frustum_; }

private:
    // The image coordinates uv of a world direction; nullopt outside the frustum (or behind the light).
    std::optional<Point2f> image_uv(Vector3f w_world) const;

    Point3f position_;
    Transform world_from_light_, light_from_world_;
    Image image_;
    float scale_;
    ProjectionFrustum frustum_;
    Distribution2D distribution_;
    Color3 power_;
};

} // namespace illum
