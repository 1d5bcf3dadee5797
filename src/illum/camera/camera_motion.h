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
        if (!is_moving() || time <= world_from_camera_.start_time()) return r;
        Matrix4 m = world_from_camera_.components(time).matrix() * camera_from_world_start_;
        Ray moved = r;
        double o[3], d[3];
        for (int i = 0; i < 3; ++i) {
            o[i] = m(i, 0) * r.o.x + m(i, 1) * r.o.y + m(i, 2) * r.o.z + m(i, 3);
            d[i] = m(i, 0) * r.d.x + m(i, 1) * r.d.y + m(i, 2) * r.d.z;
        }
        moved.o = {float(o[0]), float(o[1]), float(o[2])};
        moved.d = normalize(Vector3f{float(d[0]), float(d[1]), float(d[2])});
        return moved;
    }

private:
    AnimatedTransform world_from_camera_;
    Matrix4 camera_from_world_start_ = Matrix4::identity();
};

} // namespace illum
