// Cameras map a point on the film (raster coordinates, pixels; x right, y down), a lens sample and a
// wavelength to a world-space ray and its weight, or to no ray (vignetted: the sample counts, with zero
// radiance). Camera space follows pbrt: +x right, +y up, +z forward in the image.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "illum/camera/camera_importance.h"
#include "illum/geometry/ray.h"
#include "illum/geometry/ray_differentials.h"
#include "illum/math/transform.h"

namespace illum {

// The Fraunhofer d line (helium, 587.56 nm), where glass catalogues give n_d and V_d: the wavelength a
// camera is asked for in RGB mode.
inline constexpr float kDLineNm = 587.56f;

// A camera ray; `weight` multiplies the radiance the integrator finds along it (1 for the projective
// cameras; a lens camera's cos^4 and pupil-area factor, realistic_camera.h).
struct CameraRay {
    Ray ray;
    float weight = 1;
};

struct Screen {
    float x0, x1, y0, y1; // screen window
};

class Camera {
public:
    virtual ~Camera() = default;
    // lambda_nm: the path's hero wavelength (spectral mode) or kDLineNm (RGB mode). nullopt when the
    // lens system blocks the ray.
    virtual std::optional<CameraRay> generate_ray(Point2f p_raster, Point2f u_lens,
                                                  float lambda_nm) const = 0;
    // The ray and its differentials: the rays one pixel step away in x and y through the same lens point
    // (pbrt-v4's GenerateRayDifferential). By default (pbrt-v4's CameraBase, for the spherical and
    // realistic cameras) from rays 0.05 pixels away (-0.05 where that ray is blocked) extrapolated to
    // one pixel; rd->valid is false when neither is possible. The perspective and orthographic cameras
    // give the neighbouring pixels' rays themselves.
    virtual std::optional<CameraRay> generate_ray_differential(Point2f p_raster, Point2f u_lens,
                                                               float lambda_nm, RayDifferentials* rd) const;

    // pbrt-v4's Approximate_dp_dxy, the footprint at a point a ray without differentials found (after a
    // diffuse or glossy bounce, or a light path's): the camera's smallest differentials (found by
    // init_differentials) as rays from the camera towards p, with p's tangent plane (normal n), scaled by
    // `scale` (max(1/8, 1/sqrt(spp)), as the camera rays' are).
    void approximate_dp_dxy(Point3f p, Normal3f n, float scale, Vector3f* dpdx, Vector3f* dpdy) const;
    // pbrt-v4's FindMinimumDifferentials: the smallest change of origin and of direction (in the ray's own
    // frame) of the differentials of 512 rays along the film's diagonal through the lens centre. Called
    // once, when the scene is built (create_camera).
    void init_differentials(const Transform& world_from_camera, int width, int height);
    // True when generate_ray's direction depends on the wavelength (a dispersive lens): a spectral
    // integrator then keeps only the hero wavelength, whose path the ray is.
    virtual bool is_dispersive() const { return false; }
    // Whether generate_ray reads u_lens (a pinhole does not: the renderer then skips computing it, keeping
    // the sampler's dimensions where they were).
    virtual bool uses_lens_sample() const { return true; }

    // Camera importance (camera_importance.h), for light tracing. Cameras without it (the realistic lens
    // system) answer false and return nothing.
    virtual bool has_importance() const { return false; }
    // A lens point towards which the reference point p_ref sends light, from u; nullopt when the ray from
    // it misses the film or the camera cannot see p_ref.
    virtual std::optional<CameraWiSample> sample_wi(Point3f /*p_ref*/, Point2f /*u*/) const {
        return std::nullopt;
    }
    // W_e along a ray leaving the lens (origin on the lens, unit direction), and the raster position it
    // comes from; zero outside the film.
    virtual Importance we(const Ray& /*ray*/, Point2f* /*p_raster*/ = nullptr) const { return Importance(0); }
    virtual CameraRayPdf pdf_we(const Ray& /*ray*/) const { return {AreaPdf(0), SolidAnglePdf(0)}; }

private:
    Transform diff_world_from_camera_, diff_camera_from_world_;
    Vector3f min_pos_dx_, min_pos_dy_, min_dir_dx_, min_dir_dy_;
};

// pbrt-v4's scale of camera ray differentials for spp samples per pixel: the samples' spacing,
// 1/sqrt(spp), but at least 1/8 of a pixel.
inline float ray_differential_scale(int spp) {
    return std::max(0.125f, 1 / std::sqrt(float(std::max(spp, 1))));
}

// A perspective camera with an optional thin lens (lens_radius > 0 focuses at focal_distance).
// fov is the full angle of the shorter image axis (pbrt-v4). The default screen window spans
// [-aspect, aspect] x [-1, 1] for wide images and [-1, 1] x [-1/aspect, 1/aspect] for tall ones.
class PerspectiveCamera final : public Camera {
public:
    PerspectiveCamera(const Transform& world_from_camera, int width, int height, float fov_deg,
                      float lens_radius = 0, float focal_distance = 1e6f, const Screen* screen = nullptr);
    std::optional<CameraRay> generate_ray(Point2f p_raster, Point2f u_lens, float lambda_nm) const override;
    bool uses_lens_sample() const override { return lens_radius_ > 0; }
    std::optional<CameraRay> generate_ray_differential(Point2f p_raster, Point2f u_lens, float lambda_nm,
                                                       RayDifferentials* rd) const override;

    static Screen default_screen(int width, int height);

    // W_e = 1 / (A_film A_lens cos⁴θ) (camera_importance.cpp).
    bool has_importance() const override { return true; }
    std::optional<CameraWiSample> sample_wi(Point3f p_ref, Point2f u) const override;
    Importance we(const Ray& ray, Point2f* p_raster = nullptr) const override;
    CameraRayPdf pdf_we(const Ray& ray) const override;

private:
    // W_e of a ray with unit camera-space direction d from camera-space origin o; sets *p_raster.
    Importance we_camera(Point3f o, Vector3f d, Point2f* p_raster) const;
    Point3f to_camera(Point3f p) const;
    Vector3f to_camera(Vector3f v) const;

    Transform world_from_camera_, camera_from_world_;
    float lens_radius_, focal_distance_;
    // Raster (x, y) -> camera-space point on the z = 1 plane: (ax + bx x, ay + by y, 1).
    float ax_, bx_, ay_, by_;
    int width_, height_;
    // For the importance functions, which light tracing and BDPT call several times per connection: the
    // camera-from-world rows (linear part and translation) in floats when the transform is affine (it is
    // for every camera a scene can give; a projective one takes the Transform), and the lens in world
    // space: its centre, its axes (the images of camera x and y) and its unit normal.
    bool affine_ = false;
    Vector3f row_[3];
    float shift_[3] = {0, 0, 0};
    Point3f lens_centre_;
    Vector3f lens_x_, lens_y_, lens_normal_;
};

// An orthographic camera: parallel rays along +z; the screen window is in camera-space units.
class OrthographicCamera final : public Camera {
public:
    OrthographicCamera(const Transform& world_from_camera, int width, int height, float lens_radius = 0,
                       float focal_distance = 1e6f, const Screen* screen = nullptr);
    std::optional<CameraRay> generate_ray(Point2f p_raster, Point2f u_lens, float lambda_nm) const override;
    bool uses_lens_sample() const override { return lens_radius_ > 0; }
    std::optional<CameraRay> generate_ray_differential(Point2f p_raster, Point2f u_lens, float lambda_nm,
                                                       RayDifferentials* rd) const override;

    // Without a lens only: every ray is parallel to +z, so W_e = δ(ω - z) / A_film (A_film the screen
    // window's area in camera space): sample_wi projects the reference point onto the film plane, with
    // pdf 1 (a delta direction, as a point light's) and we = 1 / A_film. we() and pdf_we() of a given ray
    // are 0 (a delta is never hit by chance).
    bool has_importance() const override { return lens_radius_ == 0; }
    std::optional<CameraWiSample> sample_wi(Point3f p_ref, Point2f u) const override;

private:
    Transform world_from_camera_, camera_from_world_;
    float lens_radius_, focal_distance_;
    float ax_, bx_, ay_, by_;
    int width_, height_;
};

} // namespace illum
