#include "illum/camera/lens_system.h"

#include <cmath>

namespace illum {

LensVec normalize(LensVec v) { return v * (1 / std::sqrt(dot(v, v))); }

LensSystem::LensSystem(std::vector<LensInterface> interfaces, std::shared_ptr<const ApertureShape> stop_shape)
    : interfaces_(std::move(interfaces)), stop_shape_(std::move(stop_shape)) {
    set_film_distance(interfaces_.back().thickness);
}

LensSystem LensSystem::from_prescription(const LensPrescription& lens, double stop_diameter_mm,
                                         std::shared_ptr<const ApertureShape> stop_shape) {
    std::vector<LensInterface> v;
    for (const LensSurfaceSpec& s : lens.surfaces) {
        LensInterface e;
        e.radius = s.radius_mm * 1e-3;
        e.thickness = s.thickness_mm * 1e-3;
        double diameter = s.is_stop() && stop_diameter_mm > 0 ? stop_diameter_mm : s.aperture_mm;
        e.aperture_radius = diameter * 0.5e-3;
        e.n_d = s.n_d > 1 ? s.n_d : 1; // 0 (the stop's line) and 1 are air
        e.glass = CauchyGlass::from_abbe(e.n_d, e.n_d > 1 ? s.abbe : 0);
        v.push_back(e);
    }
    return LensSystem(std::move(v), std::move(stop_shape));
}

void LensSystem::set_film_distance(double d) {
    interfaces_.back().thickness = d;
    vertex_z_.assign(interfaces_.size(), 0);
    double z = 0;
    for (std::size_t i = interfaces_.size(); i-- > 0;) {
        z += interfaces_[i].thickness;
        vertex_z_[i] = z;
    }
}

bool LensSystem::dispersive() const {
    for (const LensInterface& e : interfaces_)
        if (e.glass.b != 0) return true;
    return false;
}

double LensSystem::index_after(std::size_t i, double lambda_nm) const {
    const LensInterface& e = interfaces_[i];
    return e.n_d > 1 ? e.glass.index(lambda_nm) : 1.0;
}

bool LensSystem::cross(std::size_t i, double n_from, double n_to, LensRay* r, double* weight) const {
    const LensInterface& e = interfaces_[i];
    const double zv = vertex_z_[i];
    double t;
    LensVec n;
    if (e.is_stop()) {
        if (r->d.z == 0) return false;
        t = (zv - r->o.z) / r->d.z;
        if (t < 0) return false;
    } else {
        // |o + t d - c|² = R² with c = (0, 0, zv - R) and |d| = 1: t² + 2 b t + c0 = 0. The surface is the
        // cap of the sphere around its vertex, the hemisphere where (z - z_c) has the sign of R; the
        // first crossing of that cap ahead of the ray is the hit.
        const double zc = zv - e.radius;
        LensVec oc{r->o.x, r->o.y, r->o.z - zc};
        double b = dot(oc, r->d), c0 = dot(oc, oc) - e.radius * e.radius;
        double disc = b * b - c0;
        if (disc < 0) return false;
        double s = std::sqrt(disc);
        // Stable roots (Press et al., Numerical Recipes §5.6): q = -(b + sign(b) s), t = q and c0 / q.
        double q = -(b + std::copysign(s, b));
        double t0 = q, t1 = q != 0 ? c0 / q : q;
        if (t0 > t1) std::swap(t0, t1);
        auto on_cap = [&](double tt) { return tt > 0 && (r->o.z + tt * r->d.z - zc) * e.radius > 0; };
        if (on_cap(t0))
            t = t0;
        else if (on_cap(t1))
            t = t1;
        else
            return false;
        n = (oc + r->d * t) * (1 / std::abs(e.radius)); // outward unit normal
        if (dot(n, r->d) > 0) n = -n;                   // facing the incoming ray
    }
    LensVec p = (*r)(t);
    double rho2 = p.x * p.x + p.y * p.y, ra = e.aperture_radius;
    if (e.is_stop() && stop_shape_) {
        double w = stop_shape_->transmission(p.x / ra, p.y / ra);
        if (!(w > 0)) return false;
        *weight *= w;
    } else if (rho2 > ra * ra) {
        return false;
    }
    r->o = p;
    if (e.is_stop() || n_from == n_to) return true;
    // Snell's law in vector form (Heckbert & Hanrahan 1984; PBR 4th ed. eq. 9.4): with η = n_from / n_to,
    // cos θ_i = -n·d, sin² θ_t = η² (1 - cos² θ_i); d_t = η d + (η cos θ_i - cos θ_t) n.
    double eta = n_from / n_to, cos_i = -dot(n, r->d);
    double sin2_t = eta * eta * std::max(0.0, 1 - cos_i * cos_i);
    if (sin2_t >= 1) return false; // total internal reflection: the ray leaves the image
    double cos_t = std::sqrt(1 - sin2_t);
    r->d = normalize(r->d * eta + n * (eta * cos_i - cos_t));
    return true;
}

double LensSystem::trace_from_film(const LensRay& in, double lambda_nm, LensRay* out) const {
    LensRay r{in.o, normalize(in.d)};
    double weight = 1;
    for (std::size_t i = interfaces_.size(); i-- > 0;) {
        double n_from = index_after(i, lambda_nm), n_to = i > 0 ? index_after(i - 1, lambda_nm) : 1.0;
        if (!cross(i, n_from, n_to, &r, &weight)) return 0;
    }
    if (out) *out = r;
    return weight;
}

double LensSystem::trace_from_scene(const LensRay& in, double lambda_nm, LensRay* out) const {
    LensRay r{in.o, normalize(in.d)};
    double weight = 1;
    for (std::size_t i = 0; i < interfaces_.size(); ++i) {
        double n_from = i > 0 ? index_after(i - 1, lambda_nm) : 1.0, n_to = index_after(i, lambda_nm);
        if (!cross(i, n_from, n_to, &r, &weight)) return 0;
    }
    if (out) *out = r;
    return weight;
}

} // namespace illum
