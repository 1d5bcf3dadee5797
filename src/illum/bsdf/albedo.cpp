#include "illum/bsdf/albedo.h"

#include <cmath>
#include <random>

namespace illum {

Vector3f direction_deg(double theta_deg, double phi_deg) {
    double t = theta_deg * kPiD / 180, p = phi_deg * kPiD / 180;
    return {float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t))};
}

Rgb64 albedo_quadrature(const BxDF& bxdf, Vector3f wo, int n_theta, bool reflection_only,
                        TransportMode mode) {
    Rgb64 sum{};
    int n_phi = 2 * n_theta;
    double dt = (kPiD / 2) / n_theta, dp = 2 * kPiD / n_phi;
    for (int side = 0; side < 2; ++side) {
        bool upper = side == 0;
        if (reflection_only && upper != (wo.z > 0)) continue;
        for (int i = 0; i < n_theta; ++i) {
            double t = (i + 0.5) * dt, st = std::sin(t), ct = std::cos(t);
            for (int j = 0; j < n_phi; ++j) {
                double p = (j + 0.5) * dp;
                Vector3f wi(float(st * std::cos(p)), float(st * std::sin(p)), float(upper ? ct : -ct));
                Color3 f = bxdf.f(wo, wi, mode).rgb();
                double w = ct * st * dt * dp;
                for (int c = 0; c < 3; ++c) sum[c] += f[c] * w;
            }
        }
    }
    return sum;
}

void albedo_monte_carlo(const BxDF& bxdf, Vector3f wo, int samples, std::uint64_t seed, Rgb64* mean,
                        Rgb64* se, TransportMode mode, Rgb64* ns_mean, Rgb64* ns_se) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> dist(0.0f, 1.0f);
    auto U = [&](std::mt19937_64& r) { return std::min(dist(r), 0x1.fffffep-1f); };
    Rgb64 s{}, s2{}, n{}, n2{};
    for (int i = 0; i < samples; ++i) {
        float uc = U(rng);
        Point2f u(U(rng), U(rng));
        auto bs = bxdf.sample(wo, uc, u, mode);
        if (!bs || !(bs->pdf.value > 0)) continue;
        Color3 w = bs->weight().rgb();
        for (int c = 0; c < 3; ++c) {
            s[c] += w[c];
            s2[c] += double(w[c]) * w[c];
            if (!bs->is_specular()) {
                n[c] += w[c];
                n2[c] += double(w[c]) * w[c];
            }
        }
    }
    for (int c = 0; c < 3; ++c) {
        (*mean)[c] = s[c] / samples;
        double var = std::max(0.0, s2[c] / samples - (*mean)[c] * (*mean)[c]);
        (*se)[c] = std::sqrt(var / samples);
        if (ns_mean) {
            (*ns_mean)[c] = n[c] / samples;
            (*ns_se)[c] = std::sqrt(std::max(0.0, n2[c] / samples - sqr((*ns_mean)[c])) / samples);
        }
    }
}

AlbedoEstimate directional_albedo(const BxDF& bxdf, Vector3f wo, bool delta, int n_theta, int mc_samples,
                                  std::uint64_t seed) {
    AlbedoEstimate e;
    if (!delta) {
        e.has_quadrature = true;
        e.quadrature = albedo_quadrature(bxdf, wo, n_theta, !has_flag(bxdf.flags(), kTransmission));
    }
    albedo_monte_carlo(bxdf, wo, mc_samples, seed, &e.mc, &e.mc_stderr);
    e.mc_samples = mc_samples;
    return e;
}

} // namespace illum
