// Importance of the projective cameras (camera_importance.h; PBR 4th ed. §16.1.1). Camera space is
// assumed to differ from world space by a rigid motion (possibly a reflection), so lengths and areas are
// the same in both.
#include <cmath>

#include "illum/camera/camera.h"
#include "illum/math/warp.h"

namespace illum {

namespace {
bool on_film(Point2f p, int width, int height) {
    return p.x >= 0 && p.x < float(width) && p.y >= 0 && p.y < float(height);
}
float lens_area(float lens_radius) { return lens_radius > 0 ? kPi * lens_radius * lens_radius : 1.0f; }
} // namespace

Point3f PerspectiveCamera::to_camera(Point3f p) const {
    if (!affine_) return camera_from_world_(p);
    Vector3f v(p.x, p.y, p.z);
    return {dot(row_[0], v) + shift_[0], dot(row_[1], v) + shift_[1], dot(row_[2], v) + shift_[2]};
}

Vector3f PerspectiveCamera::to_camera(Vector3f v) const {
    if (!affine_) return camera_from_world_(v);
    return {dot(row_[0], v), dot(row_[1], v), dot(row_[2], v)};
}

// W_e(p, ω) = 1 / (A_film A_lens cos⁴θ) for a ray that lands on the film, θ the angle to the viewing
// direction (PBR 4th ed. eq. 16.3): the film's density of directions per steradian is 1 / (A_film cos³θ)
// (a z = 1 plane seen from the pinhole, dA = r² dω / cos θ with r = 1 / cos θ), and the measurement's
// cos θ takes one more.
Importance PerspectiveCamera::we_camera(Point3f o, Vector3f d, Point2f* p_raster) const {
    float cos_theta = d.z;
    if (!(cos_theta > 0)) return Importance(0);
    // The ray meets the plane of focus (z = focal distance) where the pinhole ray of its film point does;
    // a pinhole's ray starts at the origin and meets z = 1.
    float plane = lens_radius_ > 0 ? focal_distance_ : 1.0f;
    Point3f p_focus = o + d * ((plane - o.z) / cos_theta);
    Point2f raster{(p_focus.x / p_focus.z - ax_) / bx_, (p_focus.y / p_focus.z - ay_) / by_};
    if (!on_film(raster, width_, height_)) return Importance(0);
    if (p_raster) *p_raster = raster;
    float film_area = std::abs(bx_ * float(width_) * by_ * float(height_));
    float cos2 = cos_theta * cos_theta;
    return Importance(1 / (film_area * lens_area(lens_radius_) * cos2 * cos2));
}

Importance PerspectiveCamera::we(const Ray& ray, Point2f* p_raster) const {
    return we_camera(to_camera(ray.o), normalize(to_camera(ray.d)), p_raster);
}

// p_pos = 1 / A_lens, p_dir = 1 / (A_film cos³θ) (PBR 4th ed. §16.1.1).
CameraRayPdf PerspectiveCamera::pdf_we(const Ray& ray) const {
    Vector3f d = normalize(to_camera(ray.d));
    if (we_camera(to_camera(ray.o), d, nullptr).value == 0) return {AreaPdf(0), SolidAnglePdf(0)};
    float cos_theta = d.z;
    float film_area = std::abs(bx_ * float(width_) * by_ * float(height_));
    return {AreaPdf(1 / lens_area(lens_radius_)),
            SolidAnglePdf(1 / (film_area * cos_theta * cos_theta * cos_theta))};
}

// A lens point uniform on the lens (the pinhole itself without one): its area density 1 / A_lens becomes a
// density of directions at the reference point, p_ω = r² / (|cos θ_lens| A_lens) (PBR 4th ed. §16.1.1).
std::optional<CameraWiSample> PerspectiveCamera::sample_wi(Point3f p_ref, Point2f u) const {
    Point2f lens = lens_radius_ > 0 ? sample_uniform_disk_concentric(u) : Point2f{0, 0};
    Point3f p_lens =
        affine_ ? lens_centre_ + lens_x_ * (lens.x * lens_radius_) + lens_y_ * (lens.y * lens_radius_)
                : world_from_camera_(Point3f{lens.x * lens_radius_, lens.y * lens_radius_, 0});
    Normal3f n_lens(lens_normal_);
    Vector3f wi = p_lens - p_ref;
    float d2 = length_squared(wi);
    if (!(d2 > 0)) return std::nullopt;
    wi = wi / std::sqrt(d2);
    Point2f raster;
    // The ray from the lens point towards p_ref, in camera space: the lens point is (x r, y r, 0).
    Importance w = we_camera(Point3f{lens.x * lens_radius_, lens.y * lens_radius_, 0},
                             normalize(to_camera(-wi)), &raster);
    if (w.value == 0) return std::nullopt;
    float cos_lens = std::abs(dot(Vector3f(n_lens), wi));
    if (!(cos_lens > 0)) return std::nullopt;
    return CameraWiSample{p_lens, n_lens, wi, w, SolidAnglePdf(d2 / (cos_lens * lens_area(lens_radius_))),
                          raster};
}

// The reference point's orthogonal projection onto the film plane z = 0, the only point that sees it.
std::optional<CameraWiSample> OrthographicCamera::sample_wi(Point3f p_ref, Point2f) const {
    if (lens_radius_ > 0) return std::nullopt;
    Point3f p = camera_from_world_(p_ref);
    if (!(p.z > 0)) return std::nullopt;
    Point2f raster{(p.x - ax_) / bx_, (p.y - ay_) / by_};
    if (!on_film(raster, width_, height_)) return std::nullopt;
    Point3f p_lens = world_from_camera_(Point3f{p.x, p.y, 0});
    Normal3f n_lens(normalize(world_from_camera_(Vector3f{0, 0, 1})));
    float film_area = std::abs(bx_ * float(width_) * by_ * float(height_));
    return CameraWiSample{p_lens,           n_lens, -Vector3f(n_lens), Importance(1 / film_area),
                          SolidAnglePdf(1), raster};
}

} // namespace illum
