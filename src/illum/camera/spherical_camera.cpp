#include "illum/camera/spherical_camera.h"

#include <utility>

#include "illum/envmap/layout.h"

namespace illum {

namespace {

// pbrt-v4's WrapEqualAreaSquare: a point just outside the square is its mirror image across the nearest
// edge with the other coordinate mirrored about 1/2, which is where the octahedral map continues across
// that edge (its edges are glued that way on the sphere).
Point2f wrap_equal_area_square(Point2f uv) {
    if (uv.x < 0) {
        uv = {-uv.x, 1 - uv.y};
    } else if (uv.x > 1) {
        uv = {2 - uv.x, 1 - uv.y};
    }
    if (uv.y < 0) {
        uv = {1 - uv.x, -uv.y};
    } else if (uv.y > 1) {
        uv = {1 - uv.x, 2 - uv.y};
    }
    return uv;
}

// pbrt-v4 computes its directions with +z up and then swaps y and z (camera +y is up).
Vector3f swap_yz(Vector3f d) { return {d.x, d.z, d.y}; }

} // namespace

std::optional<SphericalMapping> spherical_mapping_from_string(const std::string& s) {
    if (s == "equalarea") return SphericalMapping::EqualArea;
    if (s == "equirectangular") return SphericalMapping::Equirectangular;
    return std::nullopt;
}

Vector3f spherical_direction(SphericalMapping m, Point2f uv) {
    if (m == SphericalMapping::Equirectangular) {
        // Not clamped: θ slightly beyond [0, π] continues over the pole, as pbrt-v4's formula does.
        float theta = kPi * uv.y, phi = 2 * kPi * uv.x;
        float st = std::sin(theta);
        return swap_yz({st * std::cos(phi), st * std::sin(phi), std::cos(theta)});
    }
    return swap_yz(*env_direction(EnvLayout::Octahedral, wrap_equal_area_square(uv)));
}

Point2f spherical_uv(SphericalMapping m, Vector3f d) {
    return env_uv(m == SphericalMapping::Equirectangular ? EnvLayout::LatLong : EnvLayout::Octahedral,
                  swap_yz(d));
}

SphericalCamera::SphericalCamera(const Transform& world_from_camera, int width, int height,
                                 SphericalMapping mapping)
    : world_from_camera_(world_from_camera), width_(width), height_(height), mapping_(mapping) {}

std::optional<CameraRay> SphericalCamera::generate_ray(Point2f p, Point2f, float) const {
    Vector3f d = spherical_direction(mapping_, {p.x / float(width_), p.y / float(height_)});
    return CameraRay{{world_from_camera_(Point3f{0, 0, 0}), normalize(world_from_camera_(d)), kInfinity}};
}

} // namespace illum
