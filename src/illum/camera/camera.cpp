#include "illum/camera/camera.h"

#include <cmath>

#include "illum/math/warp.h"

namespace illum {

Screen PerspectiveCamera::default_screen(int width, int height) {
    float aspect = float(width) / float(height);
    if (aspect > 1) return {-aspect, aspect, -1, 1};
    return {-1, 1, -1 / aspect, 1 / aspect};
}

namespace {

// The neighbouring pixels' rays (camera space) as world-space ray differentials.
RayDifferentials offset_rays_to_world(const Transform& world_from_camera, const Ray& rx, const Ray& ry) {
    RayDifferentials rd;
    rd.rx_origin = world_from_camera(rx.o);
    rd.ry_origin = world_from_camera(ry.o);
    rd.rx_direction = normalize(world_from_camera(rx.d));
    rd.ry_direction = normalize(world_from_camera(ry.d));
    rd.valid = true;
    return rd;
}

// Raster x in [0, width] maps to screen x0..x1; raster y in [0, height] maps to y1..y0 (y down).
void raster_to_screen(const Screen& s, int width, int height, float scale, float* ax, float* bx, float* ay,
                      float* by) {
    *bx = (s.x1 - s.x0) / width * scale;
    *ax = s.x0 * scale;
    *by = -(s.y1 - s.y0) / height * scale;
    *ay = s.y1 * scale;
}

// Thin lens: the ray through the lens point that meets the pinhole ray at the plane of focus.
Ray thin_lens(Point3f p_camera_dir_origin, Vector3f dir, float lens_radius, float focal_distance, Point2f u) {
    Ray r{p_camera_dir_origin, dir, kInfinity};
    if (lens_radius <= 0) return r;
    Point2f lens = sample_uniform_disk_concentric(u);
    Point3f p_lens{lens.x * lens_radius, lens.y * lens_radius, 0};
    float ft = (focal_distance - r.o.z) / r.d.z;
    Point3f p_focus = r(ft);
    r.o = p_lens + Vector3f(r.o.x, r.o.y, 0); // the orthographic origin offset stays
    r.d = normalize(p_focus - r.o);
    return r;
}
} // namespace

PerspectiveCamera::PerspectiveCamera(const Transform& world_from_camera, int width, int height, float fov_deg,
                                     float lens_radius, float focal_distance, const Screen* screen)
    : world_from_camera_(world_from_camera), camera_from_world_(world_from_camera.inverse()),
      lens_radius_(lens_radius), focal_distance_(focal_distance), width_(width), height_(height) {
    Screen s = screen ? *screen : default_screen(width, height);
    float tan_half = std::tan(fov_deg * kPi / 360.0f);
    raster_to_screen(s, width, height, tan_half, &ax_, &bx_, &ay_, &by_);
    const Matrix4& c = camera_from_world_.matrix();
    const Matrix4& w = world_from_camera_.matrix();
    auto affine = [](const Matrix4& m) {
        return m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1;
    };
    affine_ = affine(c) && affine(w);
    for (int r = 0; r < 3; ++r) {
        row_[r] = Vector3f(float(c(r, 0)), float(c(r, 1)), float(c(r, 2)));
        shift_[r] = float(c(r, 3));
    }
    lens_centre_ = world_from_camera_(Point3f{0, 0, 0});
    lens_x_ = world_from_camera_(Vector3f{1, 0, 0});
    lens_y_ = world_from_camera_(Vector3f{0, 1, 0});
    lens_normal_ = normalize(world_from_camera_(Vector3f{0, 0, 1}));
}

std::optional<CameraRay> PerspectiveCamera::generate_ray(Point2f p, Point2f u_lens, float) const {
    Vector3f dir = normalize(Vector3f{ax_ + bx_ * p.x, ay_ + by_ * p.y, 1});
    Ray r = thin_lens({0, 0, 0}, dir, lens_radius_, focal_distance_, u_lens);
    // A pinhole's rays all leave the lens centre, transformed once.
    const Point3f o = lens_radius_ > 0 ? world_from_camera_(r.o) : lens_centre_;
    return CameraRay{{o, normalize(world_from_camera_(r.d)), kInfinity}};
}

std::optional<CameraRay> PerspectiveCamera::generate_ray_differential(Point2f p, Point2f u_lens, float lambda,
                                                                      RayDifferentials* rd) const {
    std::optional<CameraRay> cr = generate_ray(p, u_lens, lambda);
    // The neighbouring pixels' rays through the same lens point (pbrt-v4's PerspectiveCamera).
    Ray rx = thin_lens({0, 0, 0}, normalize(Vector3f{ax_ + bx_ * (p.x + 1), ay_ + by_ * p.y, 1}),
                       lens_radius_, focal_distance_, u_lens);
    Ray ry = thin_lens({0, 0, 0}, normalize(Vector3f{ax_ + bx_ * p.x, ay_ + by_ * (p.y + 1), 1}),
                       lens_radius_, focal_distance_, u_lens);
    *rd = offset_rays_to_world(world_from_camera_, rx, ry);
    return cr;
}

OrthographicCamera::OrthographicCamera(const Transform& world_from_camera, int width, int height,
                                       float lens_radius, float focal_distance, const Screen* screen)
    : world_from_camera_(world_from_camera), camera_from_world_(world_from_camera.inverse()),
      lens_radius_(lens_radius), focal_distance_(focal_distance), width_(width), height_(height) {
    Screen s = screen ? *screen : PerspectiveCamera::default_screen(width, height);
    raster_to_screen(s, width, height, 1.0f, &ax_, &bx_, &ay_, &by_);
}

std::optional<CameraRay> OrthographicCamera::generate_ray(Point2f p, Point2f u_lens, float) const {
    Point3f o{ax_ + bx_ * p.x, ay_ + by_ * p.y, 0};
    Ray r = thin_lens(o, {0, 0, 1}, lens_radius_, focal_distance_, u_lens);
    return CameraRay{{world_from_camera_(r.o), normalize(world_from_camera_(r.d)), kInfinity}};
}

std::optional<CameraRay> OrthographicCamera::generate_ray_differential(Point2f p, Point2f u_lens,
                                                                       float lambda,
                                                                       RayDifferentials* rd) const {
    std::optional<CameraRay> cr = generate_ray(p, u_lens, lambda);
    Ray rx = thin_lens({ax_ + bx_ * (p.x + 1), ay_ + by_ * p.y, 0}, {0, 0, 1}, lens_radius_, focal_distance_,
                       u_lens);
    Ray ry = thin_lens({ax_ + bx_ * p.x, ay_ + by_ * (p.y + 1), 0}, {0, 0, 1}, lens_radius_, focal_distance_,
                       u_lens);
    *rd = offset_rays_to_world(world_from_camera_, rx, ry);
    return cr;
}

} // namespace illum
