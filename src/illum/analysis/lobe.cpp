#include "illum/analysis/lobe.h"

#include <cmath>

#include "illum/math/rng.h"

namespace illum {

double LobeGrid::theta(int row) const { return (row + 0.5) * (kPiD / 2) / n_theta; }
double LobeGrid::phi(int col) const { return (col + 0.5) * (2 * kPiD) / n_phi; }

Vector3f LobeGrid::direction(int row, int col) const {
    double t = theta(row), p = phi(col);
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}

Rgb64 LobeGrid::integral_of_f() const {
    Rgb64 sum{};
    double cell = (kPiD / 2) / n_theta * (2 * kPiD) / n_phi;
    for (int r = 0; r < rows(); ++r) {
        double w = std::sin(theta(r)) * cell;
        for (int c = 0; c < n_phi; ++c)
            for (int k = 0; k < 3; ++k) sum[k] += at(r, c)[k] * w;
    }
    return sum;
}

Rgb64 LobeGrid::albedo() const {
    Rgb64 a = integral_of_f();
    for (const LobeSpike& s : spikes)
        for (int k = 0; k < 3; ++k) a[k] += s.share[k];
    return a;
}

Rgb64 lobe_value(const BxDF& bxdf, Vector3f wi, Vector3f w) {
    Color3 f = bxdf.f(wi, w, TransportMode::Importance).rgb();
    double c = std::abs(w.z);
    return {f.r * c, f.g * c, f.b * c};
}

LobeGrid sample_lobe(const BxDF& bxdf, Vector3f wi, const LobeOptions& o) {
    LobeGrid g;
    g.wi = wi;
    g.n_theta = o.n_theta;
    g.n_phi = 2 * o.n_theta;
    g.both_hemispheres = has_flag(bxdf.flags(), kTransmission) || wi.z < 0;
    g.values.resize(std::size_t(g.rows()) * std::size_t(g.n_phi));
    for (int r = 0; r < g.rows(); ++r)
        for (int c = 0; c < g.n_phi; ++c)
            g.values[std::size_t(r) * std::size_t(g.n_phi) + std::size_t(c)] =
                lobe_value(bxdf, wi, g.direction(r, c));
    // Delta spikes: stratified in the lobe-choosing number, random in the direction numbers.
    PCG32 rng(o.seed);
    for (int i = 0; i < o.spike_samples; ++i) {
        float uc = (i + 0.5f) / float(o.spike_samples);
        Point2f u{rng.uniform_float(), rng.uniform_float()}; // braces: drawn left to right
        auto s = bxdf.sample(wi, uc, u, TransportMode::Importance);
        if (!s || !s->is_specular() || !(s->pdf.value > 0)) continue;
        Color3 w = s->weight().rgb();
        Vector3f d = normalize(s->wi);
        LobeSpike* spike = nullptr;
        for (LobeSpike& k : g.spikes)
            if (length(k.direction - d) < 1e-3f) spike = &k;
        if (!spike) {
            g.spikes.push_back({d, {}});
            spike = &g.spikes.back();
        }
        for (int k = 0; k < 3; ++k) spike->share[k] += double(w[k]) / o.spike_samples;
    }
    return g;
}

std::vector<PlaneSample> lobe_in_plane(const BxDF& bxdf, Vector3f wi, int samples) {
    double phi_i = (wi.x == 0 && wi.y == 0) ? 0.0 : std::atan2(double(wi.y), double(wi.x));
    std::vector<PlaneSample> out;
    for (int i = 0; i < samples; ++i) {
        double psi = -180 + 360.0 * (i + 0.5) / samples, r = psi * kPiD / 180;
        Vector3f w(float(std::sin(r) * std::cos(phi_i)), float(std::sin(r) * std::sin(phi_i)),
                   float(std::cos(r)));
        out.push_back({psi, lobe_value(bxdf, wi, w)});
    }
    return out;
}

std::vector<AlbedoPoint> albedo_curve(const BxDF& bxdf, double phi_deg, const std::vector<double>& thetas,
                                      const LobeOptions& o) {
    std::vector<AlbedoPoint> out;
    for (double t : thetas) {
        LobeGrid g = sample_lobe(bxdf, direction_deg(t, phi_deg), o);
        out.push_back({t, g.albedo(), g.integral_of_f()});
    }
    return out;
}

} // namespace illum
