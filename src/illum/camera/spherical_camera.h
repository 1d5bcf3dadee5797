// pbrt-v4's spherical camera: every ray starts at the camera's origin and the film is the whole sphere of
// directions, unrolled by one of two mappings of the film's (u, v) = p_raster / full resolution:
//  - "equirectangular": θ = π v, φ = 2π u, the direction (sin θ cos φ, sin θ sin φ, cos θ) with its y and z
//    swapped: the top row looks along camera +y (up), the bottom row along -y, and column u at azimuth
//    φ = 2π u from camera +x towards +z (forward at u = 1/4, -x at u = 1/2);
//  - "equalarea" (the default): Clarberg's equal-area octahedral square-to-sphere map ("Fast Equal-Area
//    Mapping of the (Hemi)Sphere using SIMD", JGT 2008; the layout of envmap/layout.h), after folding a
//    (u, v) outside [0, 1]² back into it (a filter's offset may reach past the film's edge), then y and z
//    swapped as pbrt-v4 does: the image's centre looks along camera +y, its corners along -y; every pixel
//    subtends the same solid angle, 4π / (width · height).
// Both are pbrt-v4's SphericalCamera::GenerateRay. pbrt-v4 reads "screenwindow", "frameaspectratio",
// "lensradius" and "focaldistance" for this camera and ignores them; so does illum. There is no importance
// function (pbrt-v4 has none either): light tracing and BDPT refuse this camera.
#pragma once

#include <optional>
#include <string>

#include "illum/camera/camera.h"

namespace illum {

enum class SphericalMapping { EqualArea, Equirectangular };

// "equalarea" or "equirectangular".
std::optional<SphericalMapping> spherical_mapping_from_string(const std::string& s);

// The camera-space unit direction for film coordinates uv = p_raster / resolution.
Vector3f spherical_direction(SphericalMapping m, Point2f uv);
// Its inverse: the film coordinates in [0, 1]² of a camera-space unit direction.
Point2f spherical_uv(SphericalMapping m, Vector3f d);

class SphericalCamera final : public Camera {
public:
    // width, height: the film's full resolution (a crop window does not change the projection).
    SphericalCamera(const Transform& world_from_camera, int width, int height, SphericalMapping mapping);
    std::optional<CameraRay> generate_ray(Point2f p_raster, Point2f u_lens, float lambda_nm) const override;

private:
    Transform world_from_camera_;
    int width_, height_;
    SphericalMapping mapping_;
};

} // namespace illum
