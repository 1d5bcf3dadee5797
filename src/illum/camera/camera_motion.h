// A moving camera (pbrt-v4's CameraTransform over an AnimatedTransform of world_from_camera): the camera
// is built at its start transform, and each ray it generates is carried to where the camera is at the
// ray's time by world_from_camera(t) · camera_from_world(start), exact for every camera model since the
// lens moves as one body.
#pragma once

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
        return carried(world_from_camera_.components(time).matrix() * camera_from_world_start_, r);
    }
    // The other way, for the camera's importance (light tracing, bdpt, vcm): the camera model knows itself
    // at its start transform only, so a point or ray seen by the camera at `time` is carried to where it
    // lies relative to the start pose, and answers are carried back with at() / point_at().
    Ray to_start(const Ray& r, float time) const {
        if (!moves_at(time)) return r;
        return carried(start_from(time), r);
    }
    Point3f to_start(Point3f p, float time) const {
        if (!moves_at(time)) return p;
        return apply_point(start_from(time), p);
    }
    Point3f point_at(Point3f p, float time) const {
        if (!moves_at(time)) return p;
        return apply_point(world_from_camera_.components(time).matrix() * camera_from_world_start_, p);
    }
    Vector3f direction_at(Vector3f d, float time) const {
        if (!moves_at(time)) return d;
        return normalize(
            apply_direction(world_from_camera_.components(time).matrix() * camera_from_world_start_, d));
    }

private:
    bool moves_at(float time) const { return is_moving() && time > world_from_camera_.start_time(); }
    // world_from_camera(start) · camera_from_world(time): the inverse of the motion at `time`.
    Matrix4 start_from(float time) const {
        Matrix4 m = world_from_camera_.components(time).matrix() * camera_from_world_start_;
        auto inv = inverse(m);
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
