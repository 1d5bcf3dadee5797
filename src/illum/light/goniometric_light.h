// pbrt-v4's goniometric light: a point source whose intensity over the sphere of directions is given by an
// image in the equal-area octahedral layout (Clarberg 2008; envmap/layout.h), times a spectrum:
//   I(ω) = I · Y(texel containing uv(ω)),
// Y being the image's channel average (pbrt-v4 reads the "Y" channel, or averages R, G, B), looked up at the
// nearest texel as pbrt-v4 does. The image's frame has its +z (the image's centre) along the light's +y:
// pbrt-v4 swaps y and z of the light-space direction ("swapYZ"), so a goniometric diagram measured about a
// vertical axis stands up in a y-up light space.
//
// Every texel of an equal-area map covers the solid angle 4π / N², so the power is exactly
//   Φ = 4π I · mean(Y)     (pbrt-v4's GoniometricLight::Phi),
// and photons are emitted with the texels' Y as their probabilities: p(ω) = p(uv) / 4π, which makes every
// photon carry the same flux I(ω) / p(ω) = Φ (for an image without zeros).
#pragma once

#include <vector>

#include "illum/image/image.h"
#include "illum/light/light.h"
#include "illum/math/distribution.h"
#include "illum/math/transform.h"
#include "illum/radiometry/emission.h"

namespace illum {

class GoniometricLight final : public Light {
public:
    // world_from_light: the CTM at the LightSource (the position is its origin); intensity: I with scale
    // and power already applied; image: square, equal-area octahedral, non-negative.
    GoniometricLight(const Transform& world_from_light, Emission intensity, const Image& image);

    // I(ω) for the unit world direction ω leaving the light.
    Intensity3 intensity(Vector3f w_world, const SampledWavelengths& lambda) const;
    // The image's Y at the texel of direction d, given in the image's frame (for tests).
    float relative_intensity(Vector3f d_image) const;

    std::optional<LightLiSample> sample_li(const LightSampleContext& ctx, Point2f,
                                           const SampledWavelengths& lambda) const override;
    SolidAnglePdf pdf_li(const LightSampleContext&, Vector3f, const SurfaceHit*) const override {
        return SolidAnglePdf(0);
    }
    std::optional<Point3f> position() const override { return position_; }
    // Φ = 4π I mean(Y).
    Power3 power() const override;
    // Bounded as an isotropic point light of the same power (phi = 4π times the mean intensity).
    std::optional<LightBounds> bounds() const override {
        return point_bounds(position_, power().rgb().luminance());
    }
    // A direction with density p(uv) / 4π from the texels' Y: flux = I(ω) / p(ω).
    std::optional<LightLeSample> sample_le(Point2f u1, Point2f u2,
                                           const SampledWavelengths& lambda) const override;
    void pdf_le(const Ray& ray, Normal3f n, AreaPdf* pos, SolidAnglePdf* dir) const override;

private:
    // The image frame's direction of a world direction, and back (with pbrt-v4's swap of y and z).
    Vector3f image_from_world(Vector3f w) const;
    Vector3f world_from_image(Vector3f d) const;

    Point3f position_;
    Transform world_from_light_, light_from_world_;
    Emission intensity_;
    int n_ = 0;
    std::vector<float> y_; // the image's Y, row by row
    double mean_y_ = 0;
    Distribution2D distribution_;
};

} // namespace illum
