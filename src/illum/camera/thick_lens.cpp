#include "illum/camera/thick_lens.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {
// Where the ray r (in the x-z plane) reaches height x: its z.
double z_at_height(const LensRay& r, double x) { return r.o.z + (x - r.o.x) / r.d.x * r.d.z; }
} // namespace

std::optional<CardinalPoints> trace_cardinal_points(const LensSystem& lens, double lambda_nm, double h) {
    CardinalPoints cp;
    LensRay out;
    LensRay from_scene{{h, 0, lens.front_z() + 1}, {0, 0, -1}};
    if (lens.trace_from_scene(from_scene, lambda_nm, &out) == 0 || out.d.x == 0) return std::nullopt;
    cp.focal_image = z_at_height(out, 0);
    cp.principal_image = z_at_height(out, h);
    LensRay from_film{{h, 0, -1}, {0, 0, 1}};
    if (lens.trace_from_film(from_film, lambda_nm, &out) == 0 || out.d.x == 0) return std::nullopt;
    cp.focal_object = z_at_height(out, 0);
    cp.principal_object = z_at_height(out, h);
    return cp;
}

double paraxial_height(const LensSystem& lens) {
    double r = lens.interfaces().front().aperture_radius;
    for (const LensInterface& e : lens.interfaces()) r = std::min(r, e.aperture_radius);
    return 1e-4 * r;
}

std::optional<double> thick_lens_film_distance(const LensSystem& lens, const CardinalPoints& cp,
                                               double focus_distance) {
    double f = cp.efl();
    double t = focus_distance - cp.principal_object + cp.principal_image;
    double c = t * (t - 4 * f);
    if (!(f > 0) || !(c > 0)) return std::nullopt;
    double s_i = (t - std::sqrt(c)) / 2;
    return lens.film_distance() + (s_i - cp.principal_image);
}

} // namespace illum
