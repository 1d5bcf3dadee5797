// A moving camera (pbrt-v4's CameraTransform over an AnimatedTransform of world_from_camera): the camera
// is built at its start transform, and each ray it generates is carried to where the camera is at the
// ray's time by world_from_camera(t) · camera_from_world(start), exact for every camera model since the
// lens moves as one body.
#pragma once

#include <optional>

#include "illum/camera/camera.h"
#include "illum/geometry/ray.h"
#include "illum/math/animated_transform.h"

namespace illum {

class CameraMotion {
public:
    CameraMotion() = default;
    explicit CameraMotion(const AnimatedTransform& world_from_camera)
        : world_from_camera_(world_from_camera),
          camera_from_world_start_(world_from_camera.start().inverse_matrix()) {}

    bool is_moving() const { return world_from_camera_.is_animated(); }

    // A ray from the camera at its start transform, moved to the camera at `time` (direction normalised).
    Ray at(const Ray& r, float time) const {
        if (!moves_at(time)) return r;
        return carried(motion(time), r);
    }
    // The camera's importance (light tracing, bdpt, vcm) at `time`: the camera model knows itself at its
    // start transform only, so the reference point (or ray) is carried to where it lies relative to the
    // start pose, and the answer carried back: one interpolation of the motion and one inverse each.
    std::optional<CameraWiSample> sample_wi(const Camera& camera, Point3f p_ref, Point2f u,
                                            float time) const {
        if (!moves_at(time)) return camera.sample_wi(p_ref, u);
        const Matrix4 m = motion(time);
        std::optional<CameraWiSample> cs = camera.sample_wi(apply_point(start_from(m), p_ref), u);
        if (cs) {
            cs->p_lens = apply_point(m, cs->p_lens);
            cs->n_lens = Normal3f(normalize(apply_direction(m, Vector3f(cs->n_lens))));
            cs->wi = normalize(apply_direction(m, cs->wi));
        }
        return cs;
    }
    // The camera's densities for a ray leaving it at the ray's own time.
    CameraRayPdf pdf_we(const Camera& camera, const Ray& r) const {
        if (!moves_at(r.time)) return camera.pdf_we(r);
        return camera.pdf_we(carried(start_from(motion(r.time)), r));
    }

private:
    bool moves_at(float time) const { return is_moving() && time > world_from_camera_.start_time(); }
    // world_from_camera(time) · camera_from_world(start): the start pose carried to the pose at `time`.
    Matrix4 motion(float time) const {
        return world_from_camera_.components(time).matrix() * camera_from_world_start_;
    }
    // Its inverse, back to the start pose.
    static Matrix4 start_from(const Matrix4& motion) {
        auto inv = inverse(motion);
        return inv ? *inv : Matrix4::identity();
    }
    static Point3f apply_point(const Matrix4& m, Point3f p) {
        double o[3];
        for (int i = 0; i < 3; ++i) o[i] = m(i, 0) * p.x + m(i, 1) * p.y + m(i, 2) * p.z + m(i, 3);
        return {float(o[0]), float(o[1]), float(o[2])};
    }
    static Vector3f apply_direction(const Matrix4& m, Vector3f v) {
        double d[3];
        for (int i = 0; i < 3; ++i) d[i] = m(i, 0) * v.x + m(i, 1) * v.y + m(i, 2) * v.z;
        return {float(d[0]), float(d[1]), float(d[2])};
    }
    static Ray carried(const Matrix4& m, const Ray& r) {
        Ray moved = r;
        moved.o = apply_point(m, r.o);
        moved.d = normalize(apply_direction(m, r.d));
        return moved;
    }

    AnimatedTransform world_from_camera_;
    Matrix4 camera_from_world_start_ = Matrix4::identity();
};

} // namespace illum
