// Cameras map a point on the film (raster coordinates, pixels; x right, y down) and a lens sample to a
// world-space ray. Camera space follows pbrt: +x right, +y up, +z forward in the image.
#pragma once

#include "illum/geometry/ray.h"
#include "illum/math/transform.h"

namespace illum {

struct Screen {
    float x0, x1, y0, y1; // screen window
};

class Camera {
public:
    virtual ~Camera() = default;
    virtual Ray generate_ray(Point2f p_raster, Point2f u_lens) const = 0;
};

// A perspective camera with an optional thin lens (lens_radius > 0 focuses at focal_distance).
// fov is the full angle of the shorter image axis (pbrt-v4). The default screen window spans
// [-aspect, aspect] x [-1, 1] for wide images and [-1, 1] x [-1/aspect, 1/aspect] for tall ones.
class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Transform& world_from_camera, int width, int height, float fov_deg,
                      float lens_radius = 0, float focal_distance = 1e6f, const Screen* screen = nullptr);
    Ray generate_ray(Point2f p_raster, Point2f u_lens) const override;

    static Screen default_screen(int width, int height);

private:
    Transform world_from_camera_;
    float lens_radius_, focal_distance_;
    // Raster (x, y) -> camera-space point on the z = 1 plane: (ax + bx x, ay + by y, 1).
    float ax_, bx_, ay_, by_;
};

// An orthographic camera: parallel rays along +z; the screen window is in camera-space units.
class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const Transform& world_from_camera, int width, int height, float lens_radius = 0,
                       float focal_distance = 1e6f, const Screen* screen = nullptr);
    Ray generate_ray(Point2f p_raster, Point2f u_lens) const override;

private:
    Transform world_from_camera_;
    float lens_radius_, focal_distance_;
    float ax_, bx_, ay_, by_;
};

} // namespace illum
