// Environment-map layouts: how a direction of the sphere maps to image coordinates (u, v) in [0, 1]²
// (u along a row from the left, v down the rows from the top) and back, with the Jacobian dω/(du dv).
//
// Directions are in the map's own frame, +z up (pbrt's convention for environment lights).
//  - LatLong (equirectangular): u = φ / 2π with φ = atan2(y, x) in [0, 2π), v = θ / π with θ from +z
//    (pbrt-v3 and Mitsuba's convention). dω = sin θ dθ dφ = 2π² sin θ du dv.
//  - Octahedral: the equal-area octahedral map of Clarberg ("Fast Equal-Area Mapping of the (Hemi)Sphere
//    using SIMD", JGT 2008), as pbrt-v4 writes environment maps: square images, +z at the centre, -z at
//    the four corners. Equal area: dω = 4π du dv everywhere.
//  - MirrorBall: a photograph of a mirror sphere seen from far away (orthographic). In the probe frame
//    (camera on +Zp looking along -Zp, image right +Xp, image up +Yp) the disk point (a, b), a² + b² <= 1,
//    has normal n = (a, b, √(1 - a² - b²)) and reflects the view ray into d = 2 n_z n - (0, 0, 1). The
//    map is equal-area in the disk: θ = 2 asin r, so dω = 4 da db = 16 du dv.
//  - Angular (Debevec's light-probe angular map): r = θ / π with θ from +Zp: dω = π² sin θ / θ da db.
//  - Cubemap: a horizontal strip of six square faces +X, -X, +Y, -Y, +Z, -Z (OpenGL face orientation);
//    dω = 24 / (1 + s² + t²)^{3/2} du dv with (s, t) in [-1, 1]² the face coordinates.
// The probe layouts (mirror ball, angular) put the probe frame in the map's frame with Xp = +x,
// Yp = +z (image up is up), Zp = -y: the centre of the probe image looks along -y.
#pragma once

#include <optional>
#include <string>

#include "illum/math/vector.h"

namespace illum {

enum class EnvLayout { LatLong, Octahedral, MirrorBall, Angular, Cubemap };

const char* to_string(EnvLayout l);
// "latlong" (also "equirect", "equirectangular"), "octahedral", "mirrorball", "angular", "cubemap".
std::optional<EnvLayout> env_layout_from_string(const std::string& s);
// width / height of the layout's images: 2 (latlong), 6 (cubemap), 1 otherwise.
int env_layout_aspect(EnvLayout l);
// Throws illum::Error naming `what` when a width x height image cannot hold the layout.
void check_env_layout_size(EnvLayout l, int width, int height, const std::string& what);

// The unit direction for image coordinates uv; nullopt outside the layout's domain (the corners of a
// mirror-ball or angular image).
std::optional<Vector3f> env_direction(EnvLayout l, Point2f uv);
// The image coordinates of a unit direction (always defined).
Point2f env_uv(EnvLayout l, Vector3f d);
// dω / (du dv) at uv: solid angle per unit of image-coordinate area; 0 outside the domain.
float env_jacobian(EnvLayout l, Point2f uv);

} // namespace illum
