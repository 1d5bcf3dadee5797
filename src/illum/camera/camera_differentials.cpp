// The cameras' ray differentials shared by every camera: pbrt-v4's CameraBase::GenerateRayDifferential
// (finite differences of generate_ray), FindMinimumDifferentials and Approximate_dp_dxy (PBR 4th ed.
// §5.2.2 and §10.1.2).
#include <limits>

#include "illum/camera/camera.h"
#include "illum/math/frame.h"

namespace illum {

namespace {

// The shortest rotation taking the unit vector a to +z (Rodrigues' formula with k = a × z, c = a·z:
// R v = c v + k × v + k (k·v) / (1 + c)), and its inverse; a half turn about x when a is (nearly) -z.
struct RotationToZ {
    Vector3f k;
    float c = 1;
    bool flip = false;
    explicit RotationToZ(Vector3f a) {
        c = a.z;
        flip = c < -0.9999f;
        k = Vector3f(a.y, -a.x, 0); // a × (0, 0, 1)
    }
    Vector3f apply(Vector3f v, float sign) const {
        if (flip) return {v.x, -v.y, -v.z};
        Vector3f kk = k * sign;
        return v * c + cross(kk, v) + kk * (dot(kk, v) / (1 + c));
    }
    Vector3f operator()(Vector3f v) const { return apply(v, 1); }
    Vector3f inverse(Vector3f v) const { return apply(v, -1); }
};

} // namespace

std::optional<CameraRay> Camera::generate_ray_differential(Point2f p, Point2f u_lens, float lambda,
                                                           RayDifferentials* rd) const {
    std::optional<CameraRay> cr = generate_ray(p, u_lens, lambda);
    rd->valid = false;
    if (!cr) return cr;
    const Ray& r = cr->ray;
    bool found[2] = {false, false};
    for (int axis = 0; axis < 2; ++axis)
        for (float eps : {0.05f, -0.05f}) {
            Point2f ps = p;
            (axis == 0 ? ps.x : ps.y) += eps;
            std::optional<CameraRay> shifted = generate_ray(ps, u_lens, lambda);
            if (!shifted) continue;
            Point3f o = r.o + (shifted->ray.o - r.o) / eps;
            Vector3f d = r.d + (shifted->ray.d - r.d) / eps;
            if (axis == 0)
                rd->rx_origin = o, rd->rx_direction = d;
            else
                rd->ry_origin = o, rd->ry_direction = d;
            found[axis] = true;
            break;
        }
    rd->valid = found[0] && found[1];
    return cr;
}

void Camera::init_differentials(const Transform& world_from_camera, int width, int height) {
    diff_world_from_camera_ = world_from_camera;
    diff_camera_from_world_ = world_from_camera.inverse();
    const float inf = std::numeric_limits<float>::infinity();
    Vector3f pos[2] = {{inf, inf, inf}, {inf, inf, inf}}, dir[2] = {{inf, inf, inf}, {inf, inf, inf}};
    const int n = 512;
    for (int i = 0; i < n; ++i) {
        Point2f p_film{float(i) / (n - 1) * width, float(i) / (n - 1) * height};
        RayDifferentials rd;
        std::optional<CameraRay> cr = generate_ray_differential(p_film, {0.5f, 0.5f}, kDLineNm, &rd);
        if (!cr || !rd.valid) continue;
        const Ray& r = cr->ray;
        Vector3f dox = diff_camera_from_world_(rd.rx_origin - r.o),
                 doy = diff_camera_from_world_(rd.ry_origin - r.o);
        if (length(dox) < length(pos[0])) pos[0] = dox;
        if (length(doy) < length(pos[1])) pos[1] = doy;
        Frame f = Frame::from_z(normalize(r.d));
        Vector3f df = f.to_local(normalize(r.d));
        Vector3f dxf = normalize(f.to_local(normalize(rd.rx_direction)));
        Vector3f dyf = normalize(f.to_local(normalize(rd.ry_direction)));
        if (length(dxf - df) < length(dir[0])) dir[0] = dxf - df;
        if (length(dyf - df) < length(dir[1])) dir[1] = dyf - df;
    }
    // No ray at all (a lens that blocks the diagonal): no footprint rather than an infinite one.
    auto finite_or_zero = [](Vector3f v) { return is_finite(v) ? v : Vector3f(); };
    min_pos_dx_ = finite_or_zero(pos[0]), min_pos_dy_ = finite_or_zero(pos[1]);
    min_dir_dx_ = finite_or_zero(dir[0]), min_dir_dy_ = finite_or_zero(dir[1]);
}

void Camera::approximate_dp_dxy(Point3f p, Normal3f n, float scale, Vector3f* dpdx, Vector3f* dpdy) const {
    // In camera space turned so that p lies on +z: p' = (0, 0, |p|), the tangent plane n'·x = n'_z |p|.
    Vector3f pc = Vector3f(diff_camera_from_world_(p));
    float dist = length(pc);
    *dpdx = *dpdy = Vector3f();
    if (!(dist > 0)) return;
    RotationToZ down(pc / dist);
    Vector3f nd = down(Vector3f(diff_camera_from_world_(n)));
    float d = nd.z * dist;
    Point3f pd(0, 0, dist);
    // The smallest differential rays from the origin along +z meet that plane at px, py.
    auto offset = [&](Vector3f o, Vector3f dir) {
        Vector3f rd = Vector3f(0, 0, 1) + dir;
        float t = (d - dot(nd, o)) / dot(nd, rd);
        Vector3f v = diff_world_from_camera_(down.inverse((Point3f(o) + rd * t) - pd)) * scale;
        return is_finite(v) ? v : Vector3f();
    };
    *dpdx = offset(min_pos_dx_, min_dir_dx_);
    *dpdy = offset(min_pos_dy_, min_dir_dy_);
}

} // namespace illum
