// Henyey-Greenstein sampling against its density: a chi-square test over (cos θ, φ) about the incident
// direction for several g (expected counts from p() integrated by Simpson's rule; bins expecting fewer
// than 5 samples pooled; significance 1% Sidak-corrected over the four cases), the returned pdf against
// p(cos θ), p's normalisation, and the test's power: a sampler of another g is rejected.
#include <gtest/gtest.h>

#include "illum/analysis/stats.h"
#include "illum/math/rng.h"
#include "illum/medium/henyey_greenstein.h"

namespace illum {
namespace {

constexpr int kCosBins = 40, kPhiBins = 12;

// The integral of p over cos θ in [a, b] (times 2π: the solid angle of the band).
double band_probability(const HenyeyGreenstein& hg, double a, double b) {
    const int n = 200;
    double h = (b - a) / n, s = 0;
    for (int i = 0; i <= n; ++i) s += ((i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2)) * hg.p(float(a + i * h));
    return 2 * kPi * s * h / 3;
}

// p-value of `sampler`'s directions against `model`'s density, and the largest |pdf - p(cos)| / p.
double chi_square(const HenyeyGreenstein& sampler, const HenyeyGreenstein& model, int n, std::uint64_t seed,
                  double* worst_pdf) {
    PCG32 rng(seed);
    Vector3f w = normalize(Vector3f(0.3f, -0.5f, 0.8f));
    Frame f = Frame::from_z(w);
    std::vector<double> observed(kCosBins * kPhiBins, 0.0);
    *worst_pdf = 0;
    for (int i = 0; i < n; ++i) {
        float pdf;
        Vector3f wi = sampler.sample(w, {rng.uniform_float(), rng.uniform_float()}, &pdf);
        Vector3f l = f.to_local(wi);
        float c = std::clamp(l.z, -1.0f, 1.0f);
        *worst_pdf = std::max(*worst_pdf, double(std::abs(pdf - sampler.p(c)) / sampler.p(c)));
        double phi = std::atan2(l.y, l.x) + kPi;
        int ci = std::min(kCosBins - 1, int((c + 1) / 2 * kCosBins));
        int pi = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
        observed[std::size_t(ci * kPhiBins + pi)] += 1;
    }
    double stat = 0, pool_o = 0, pool_e = 0;
    int dof = -1;
    for (int ci = 0; ci < kCosBins; ++ci) {
        double a = -1 + 2.0 * ci / kCosBins, b = -1 + 2.0 * (ci + 1) / kCosBins;
        double e = band_probability(model, a, b) / kPhiBins * n;
        for (int pi = 0; pi < kPhiBins; ++pi) {
            double o = observed[std::size_t(ci * kPhiBins + pi)];
            if (e < 5) {
                pool_o += o;
                pool_e += e;
            } else {
                stat += (o - e) * (o - e) / e;
                ++dof;
            }
        }
    }
    if (pool_e > 0) {
        stat += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++dof;
    }
    return chi_square_survival(stat, std::max(dof, 1));
}

TEST(HenyeyGreenstein, IsNormalised) {
    for (float g : {-0.7f, 0.0f, 0.3f, 0.9f}) {
        HenyeyGreenstein hg{g};
        double total = 0;
        for (int i = 0; i < 400; ++i) total += band_probability(hg, -1 + i / 200.0, -1 + (i + 1) / 200.0);
        EXPECT_NEAR(total, 1, 1e-5) << g; // p() is float
    }
}

TEST(HenyeyGreenstein, SampleMatchesPByChiSquare) {
    const double alpha = sidak_significance(0.01, 4);
    std::uint64_t seed = 5;
    for (float g : {-0.7f, 0.0f, 0.3f, 0.9f}) {
        HenyeyGreenstein hg{g};
        double worst_pdf;
        double p = chi_square(hg, hg, 200000, seed++, &worst_pdf);
        EXPECT_GT(p, alpha) << "g " << g;
        EXPECT_LT(worst_pdf, 1e-4) << "g " << g; // sample's pdf is p(cos θ)
    }
}

TEST(HenyeyGreenstein, ChiSquareRejectsAnotherG) {
    for (float g : {-0.7f, 0.0f, 0.3f, 0.9f}) {
        double worst_pdf;
        double p = chi_square(HenyeyGreenstein{g + 0.05f}, HenyeyGreenstein{g}, 200000, 17, &worst_pdf);
        EXPECT_LT(p, 1e-6) << "g " << g;
    }
}

} // namespace
} // namespace illum
