#include "illum/analysis/weighted_histogram_test.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/core.h>

#include "illum/analysis/stats.h"
#include "illum/math/rng.h"

namespace illum {

namespace {
struct Moments {
    double sum = 0, sum2 = 0;
    int count = 0;
    void add(double x) {
        sum += x;
        sum2 += x * x;
        ++count;
    }
};
double scalar(Color3 c) { return (double(c.r) + c.g + c.b) / 3; }
} // namespace

WeightedHistogramResult weighted_histogram_test(const BxDF& bxdf, Vector3f wo, TransportMode mode,
                                                int samples, int nc, int np, int f_per_bin,
                                                std::uint64_t seed, int min_hits) {
    WeightedHistogramResult res;
    const float side = wo.z < 0 ? -1.0f : 1.0f; // bins cover wo's hemisphere
    auto bin_of = [&](Vector3f w) {
        float c = std::clamp(w.z * side, 0.0f, 1.0f);
        int ic = std::min(int((1 - c) * float(nc)), nc - 1);
        float phi = std::atan2(w.y, w.x);
        if (phi < 0) phi += 2 * kPi;
        int ip = std::min(int(phi / (2 * kPi) * float(np)), np - 1);
        return std::size_t(ic) * np + ip;
    };
    const std::size_t nbins = std::size_t(nc) * np;

    // A: the sample weights, per bin.
    std::vector<Moments> a(nbins);
    PCG32 rng(seed, 0x5A3);
    for (int i = 0; i < samples; ++i) {
        float uc = rng.uniform_float();
        Point2f u{rng.uniform_float(), rng.uniform_float()}; // braces: drawn left to right
        auto s = bxdf.sample(wo, uc, u, mode);
        if (!s || s->is_specular() || !(s->pdf.value > 0) || s->wi.z * side <= 0) continue;
        a[bin_of(s->wi)].add(scalar(s->weight().rgb()));
    }

    // B: stratified f |cos| over each bin. Bin (ic, ip) spans cos θ in [1 - (ic+1)/nc, 1 - ic/nc].
    const double omega = 2 * kPiD / double(nbins);
    const int k = std::max(1, int(std::lround(std::sqrt(double(f_per_bin)))));
    std::vector<Moments> b(nbins);
    for (int ic = 0; ic < nc; ++ic)
        for (int ip = 0; ip < np; ++ip)
            for (int sc = 0; sc < k; ++sc)
                for (int sp = 0; sp < k; ++sp) {
                    double c = 1 - (ic + (sc + rng.uniform_double()) / k) / nc;
                    double phi = 2 * kPiD * (ip + (sp + rng.uniform_double()) / k) / np;
                    double st = std::sqrt(std::max(0.0, 1 - c * c));
                    Vector3f wi(float(st * std::cos(phi)), float(st * std::sin(phi)), float(c * side));
                    b[std::size_t(ic) * np + ip].add(scalar(bxdf.f(wo, wi, mode).rgb()) * c);
                }

    // Per-bin z scores; sparse bins pooled.
    const double n = samples;
    double stat = 0;
    Moments pool_a;
    double pool_b = 0, pool_var_b = 0;
    auto b_estimate = [&](const Moments& m, double* var) {
        double mean = m.sum / m.count;
        double s2 = std::max(0.0, (m.sum2 - m.count * mean * mean) / std::max(1, m.count - 1));
        *var = omega * omega * s2 / m.count;
        return omega * mean;
    };
    auto z_score = [&](double sum, double sum2, double bv, double bvar) {
        double av = sum / n, avar = std::max(0.0, sum2 / n - av * av) / n;
        double var = avar + bvar;
        if (!(var > 0)) return av == bv ? 0.0 : 1e9;
        return (av - bv) / std::sqrt(var);
    };
    for (std::size_t i = 0; i < nbins; ++i) {
        double bvar, bv = b_estimate(b[i], &bvar);
        if (a[i].count < min_hits) {
            pool_a.sum += a[i].sum;
            pool_a.sum2 += a[i].sum2;
            pool_a.count += a[i].count;
            pool_b += bv;
            pool_var_b += bvar;
            continue;
        }
        double z = z_score(a[i].sum, a[i].sum2, bv, bvar);
        stat += z * z;
        ++res.dof;
        if (std::abs(z) > std::abs(res.worst_z)) {
            res.worst_z = z;
            int ic = int(i) / np, ip = int(i) % np;
            res.detail =
                fmt::format("worst bin cos θ [{:.3f}, {:.3f}], φ [{:.0f}°, {:.0f}°]: sampled {:.5g}, "
                            "f() {:.5g}, z = {:.2f}",
                            1 - double(ic + 1) / nc, 1 - double(ic) / nc, 360.0 * ip / np,
                            360.0 * (ip + 1) / np, a[i].sum / n, bv, z);
        }
    }
    if (pool_a.count > 0 || pool_b > 0) {
        double z = z_score(pool_a.sum, pool_a.sum2, pool_b, pool_var_b);
        stat += z * z;
        ++res.dof;
    }
    res.statistic = stat;
    res.p_value = res.dof > 0 ? chi_square_survival(stat, res.dof) : 1;
    res.detail =
        fmt::format("{} bins, statistic {:.1f}, p = {:.3g}; {}", res.dof, stat, res.p_value, res.detail);
    return res;
}

} // namespace illum
