// The majorant walk (DDA) of the grid media, and transmittance by delta tracking and ratio tracking
// (sample_t_maj) against closed forms: exp(-σ_t d) in a homogeneous slab, and exp(-∫ σ_t) along rays
// through a uniformgrid medium, the integral by Simpson's rule over the trilinear density, in RGB and
// spectral mode. Tolerances are 5 standard errors of each estimate (Bernoulli for delta tracking, the
// sample variance for ratio tracking) plus the quadrature's error.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "illum/math/rng.h"
#include "illum/medium/sample_majorant.h"
#include "illum/medium/uniform_grid_medium.h"
#include "medium_test_util.h"

namespace illum {
namespace {

using test::DescBuilder;

Vector3f random_direction(PCG32& rng) {
    float z = 1 - 2 * rng.uniform_float(), phi = 2 * kPi * rng.uniform_float(),
          r = std::sqrt(std::max(0.0f, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// The test's own clip: the ray in medium space (double) against the box, t in [0, tmax].
bool clip_ray(const Transform& world_from_medium, Point3f p0, Point3f p1, const Ray& r, double tmax,
              double* t0, double* t1) {
    const Matrix4& m = world_from_medium.inverse_matrix();
    double o[3], d[3];
    for (int i = 0; i < 3; ++i) {
        o[i] = m(i, 0) * r.o.x + m(i, 1) * r.o.y + m(i, 2) * r.o.z + m(i, 3);
        d[i] = m(i, 0) * r.d.x + m(i, 1) * r.d.y + m(i, 2) * r.d.z;
    }
    double lo = 0, hi = tmax;
    for (int a = 0; a < 3; ++a) {
        double a0 = p0[a], a1 = p1[a];
        if (d[a] == 0) {
            if (o[a] < a0 || o[a] > a1) return false;
            continue;
        }
        double tn = (a0 - o[a]) / d[a], tf = (a1 - o[a]) / d[a];
        if (tn > tf) std::swap(tn, tf);
        lo = std::max(lo, tn);
        hi = std::min(hi, tf);
    }
    *t0 = lo;
    *t1 = hi;
    return lo < hi;
}

struct GridSetup {
    Transform t = test::test_transform();
    Point3f p0{-1, 0, 0.5f}, p1{1, 2, 1.5f};
    CreatedMedium cm;
};

GridSetup random_grid(std::uint64_t seed, int nx, int ny, int nz, Color3 sigma_a, Color3 sigma_s) {
    GridSetup g;
    PCG32 rng(seed);
    std::vector<double> d(std::size_t(nx * ny * nz));
    for (double& v : d) v = rng.uniform_float() < 0.3f ? 0.0 : 2.5 * rng.uniform_double();
    DescBuilder b("uniformgrid", g.t);
    b.res(nx, ny, nz).f("density", d).p3("p0", g.p0).p3("p1", g.p1);
    b.rgb("sigma_a", {sigma_a.r, sigma_a.g, sigma_a.b}).rgb("sigma_s", {sigma_s.r, sigma_s.g, sigma_s.b});
    g.cm = b.create();
    return g;
}

TEST(MajorantDDA, SegmentsAreContiguousCoverTheClippedRangeAndBoundTheDensity) {
    // σ_t = 1, so a segment's majorant is the majorant grid's value and sample_point's σ_t the density.
    GridSetup g = random_grid(21, 5, 4, 6, Color3(0.7f), Color3(0.3f));
    const Medium& m = *g.cm.medium;
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    PCG32 rng(99);
    int hits = 0, checked_points = 0;
    for (int i = 0; i < 400; ++i) {
        Point3f mo{-2 + 4 * rng.uniform_float(), -1 + 4 * rng.uniform_float(),
                   -0.5f + 3 * rng.uniform_float()};
        // Half of the rays aim into the box, the others go anywhere.
        Vector3f dir = random_direction(rng);
        if (i % 2 == 0) {
            Point3f target =
                g.p0 + Vector3f{2 * rng.uniform_float(), 2 * rng.uniform_float(), rng.uniform_float()};
            dir = g.t(target) - g.t(mo);
            dir = dir / length(dir);
        }
        Ray r{g.t(mo), dir};
        float tmax = i % 3 == 0 ? kInfinity : 6 * rng.uniform_float();
        double t0, t1;
        bool expect_hit = clip_ray(g.t, g.p0, g.p1, r, tmax, &t0, &t1);
        MajorantIterator it = m.sample_ray(r, tmax, rgb);
        std::vector<MajorantSegment> segs;
        while (auto s = it.next()) {
            segs.push_back(*s);
            ASSERT_LT(segs.size(), 1000u);
        }
        if (!expect_hit || t1 - t0 < 1e-4) {
            // A miss (or a graze the float clip may or may not catch): nothing, or next to nothing.
            double covered = segs.empty() ? 0 : segs.back().t1 - segs.front().t0;
            EXPECT_LT(covered, 1e-3) << "ray " << i;
            continue;
        }
        ++hits;
        ASSERT_FALSE(segs.empty()) << "ray " << i;
        double tol = 1e-4 * (1 + t1);
        EXPECT_NEAR(segs.front().t0, t0, tol) << "ray " << i;
        EXPECT_NEAR(segs.back().t1, t1, tol) << "ray " << i;
        for (std::size_t k = 0; k < segs.size(); ++k) {
            EXPECT_LE(segs[k].t0, segs[k].t1);
            if (k + 1 < segs.size()) {
                EXPECT_EQ(segs[k].t1, segs[k + 1].t0) << "ray " << i << " segment " << k;
            }
            float len = segs[k].t1 - segs[k].t0;
            if (len < 1e-5f) continue;
            for (int j = 0; j < 4; ++j) {
                float t = segs[k].t0 + len * (0.05f + 0.9f * rng.uniform_float());
                MediumProperties mp = m.sample_point(r(t), rgb);
                float sigma_t = mp.sigma_a[0] + mp.sigma_s[0];
                EXPECT_GE(segs[k].sigma_maj[0], sigma_t - 1e-4f) << "ray " << i << " t " << t;
                ++checked_points;
            }
        }
    }
    EXPECT_GT(hits, 150);
    EXPECT_GT(checked_points, 2000);
}

TEST(MajorantDDA, MajorantGridHoldsTheLargestInfluencingSample) {
    // A single non-zero sample in a 16^3 grid (one sample per majorant voxel) reaches its own voxel and
    // its 26 neighbours (each within half a voxel of it), and no further.
    std::vector<double> d(16 * 16 * 16, 0.0);
    d[(5 * 16 + 7) * 16 + 3] = 2; // x 3, y 7, z 5
    DescBuilder b("uniformgrid");
    b.res(16, 16, 16).f("density", d);
    CreatedMedium cm = b.create();
    const MajorantGrid& mg = dynamic_cast<const UniformGridMedium&>(*cm.medium).majorant_grid();
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                bool near = std::abs(x - 3) <= 1 && std::abs(y - 7) <= 1 && std::abs(z - 5) <= 1;
                EXPECT_EQ(mg.at(x, y, z), near ? 2.0f : 0.0f) << x << " " << y << " " << z;
            }
}

// Transmittance estimates along one ray: the mean and standard error per lane.
struct Estimate {
    SampledSpectrum mean, se;
};

Estimate delta_tracking(const Medium& m, Ray r, float tmax, const SampledWavelengths& w, int n, PCG32& rng) {
    r.medium = &m;
    Estimate e;
    for (int c = 0; c < kSpectrumSamples; ++c) {
        int escaped = 0;
        for (int i = 0; i < n; ++i) {
            bool absorbed = false;
            sample_t_maj(
                r, tmax, rng.uniform_float(), rng, w, c,
                [&](Point3f, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum) {
                    float sigma_t = mp.sigma_a[c] + mp.sigma_s[c];
                    if (rng.uniform_float() < sigma_t / sigma_maj[c]) {
                        absorbed = true;
                        return false;
                    }
                    return true;
                });
            escaped += !absorbed;
        }
        e.mean[c] = float(escaped) / float(n);
    }
    return e;
}

// pbrt-v4's ratio tracking (TraceTransmittance) with channel 0 sampling the tentative collisions: each
// collision weighs T_maj σ_n / (T_maj[0] σ_maj[0]), the end T_maj / T_maj[0].
Estimate ratio_tracking(const Medium& m, Ray r, float tmax, const SampledWavelengths& w, int n, PCG32& rng) {
    r.medium = &m;
    double sum[kSpectrumSamples] = {}, sum2[kSpectrumSamples] = {};
    for (int i = 0; i < n; ++i) {
        SampledSpectrum tr(1.0f);
        SampledSpectrum t_maj = sample_t_maj(
            r, tmax, rng.uniform_float(), rng, w, 0,
            [&](Point3f, const MediumProperties& mp, SampledSpectrum sigma_maj, SampledSpectrum tm) {
                SampledSpectrum sigma_n = sigma_maj - mp.sigma_a - mp.sigma_s;
                tr *= tm * sigma_n / (tm[0] * sigma_maj[0]);
                return tr.max_component() > 0;
            });
        if (t_maj[0] > 0) tr *= t_maj / t_maj[0];
        for (int c = 0; c < kSpectrumSamples; ++c) {
            sum[c] += tr[c];
            sum2[c] += double(tr[c]) * tr[c];
        }
    }
    Estimate e;
    for (int c = 0; c < kSpectrumSamples; ++c) {
        double mean = sum[c] / n, var = std::max(0.0, sum2[c] / n - mean * mean);
        e.mean[c] = float(mean);
        e.se[c] = float(std::sqrt(var / (n - 1)));
    }
    return e;
}

void expect_transmittance(const Estimate& delta, const Estimate& ratio, const SampledSpectrum& exact, int n,
                          double quadrature_tol, const std::string& what) {
    for (int c = 0; c < kSpectrumSamples; ++c) {
        double p = exact[c], se_delta = std::sqrt(std::max(p * (1 - p), 1e-12) / n);
        EXPECT_NEAR(delta.mean[c], p, 5 * se_delta + quadrature_tol) << what << " delta lane " << c;
        EXPECT_NEAR(ratio.mean[c], p, 5 * ratio.se[c] + quadrature_tol + 1e-7) << what << " ratio lane " << c;
    }
}

TEST(Transmittance, HomogeneousSlabIsExpOfMinusSigmaTD) {
    // σ_maj = σ_t: every tentative collision is real, so both estimators are Bernoulli trials of
    // exp(-σ_t d) in the sampling channel (ratio tracking's other lanes weigh the survivors by
    // exp(-(σ_t - σ_t[0]) d)).
    DescBuilder b("homogeneous");
    b.rgb("sigma_a", {0.2, 0.5, 0.05}).rgb("sigma_s", {0.3, 0.1, 0.6});
    CreatedMedium cm = b.create();
    PCG32 rng(1234);
    const int n = 20000;
    for (bool spectral : {false, true})
        for (float d : {0.5f, 1.7f, 4.0f}) {
            SampledWavelengths w =
                spectral ? test::spectral_wavelengths(0.21f) : SampledWavelengths::rgb_mode();
            MediumProperties mp = cm.medium->sample_point({0, 0, 0}, w);
            SampledSpectrum exact = exp(-(mp.sigma_a + mp.sigma_s) * d);
            Ray r{{1, 2, 3}, Vector3f(0.6f, 0, 0.8f)};
            Estimate de = delta_tracking(*cm.medium, r, d, w, n, rng);
            Estimate re = ratio_tracking(*cm.medium, r, d, w, n, rng);
            expect_transmittance(de, re, exact, n, 1e-6, fmt::format("spectral {} d {}", spectral, d));
        }
}

TEST(Transmittance, UniformGridMatchesTheIntegratedDensity) {
    GridSetup g = random_grid(8, 4, 3, 5, Color3(0.3f, 0.6f, 0.9f), Color3(0.5f, 0.2f, 0.1f));
    const Medium& m = *g.cm.medium;
    PCG32 rng(77);
    const int n = 20000;
    int tested = 0;
    for (int ray = 0; ray < 6; ++ray) {
        // From outside the box towards a point inside it; every other ray stops inside.
        Point3f target =
            g.p0 + Vector3f{2 * rng.uniform_float(), 2 * rng.uniform_float(), rng.uniform_float()};
        Point3f from = target + random_direction(rng) * 4;
        Vector3f dir = g.t(target) - g.t(from);
        float dist = length(dir);
        Ray r{g.t(from), dir / dist};
        float tmax = ray % 2 ? dist : kInfinity;
        double t0, t1;
        ASSERT_TRUE(clip_ray(g.t, g.p0, g.p1, r, tmax, &t0, &t1));
        for (bool spectral : {false, true}) {
            SampledWavelengths w =
                spectral ? test::spectral_wavelengths(rng.uniform_float()) : SampledWavelengths::rgb_mode();
            // Simpson's rule over the clipped range (the density is trilinear between sample planes, so
            // 20000 intervals leave an error far below the estimators').
            const int k = 20000;
            double h = (t1 - t0) / k, tau[kSpectrumSamples] = {};
            for (int i = 0; i <= k; ++i) {
                double wgt = (i == 0 || i == k) ? 1 : (i % 2 ? 4 : 2);
                MediumProperties mp = m.sample_point(r(float(t0 + i * h)), w);
                for (int c = 0; c < kSpectrumSamples; ++c) tau[c] += wgt * (mp.sigma_a[c] + mp.sigma_s[c]);
            }
            SampledSpectrum exact;
            for (int c = 0; c < kSpectrumSamples; ++c) exact[c] = float(std::exp(-tau[c] * h / 3));
            Estimate de = delta_tracking(m, r, tmax, w, n, rng);
            Estimate re = ratio_tracking(m, r, tmax, w, n, rng);
            expect_transmittance(de, re, exact, n, 2e-4, fmt::format("ray {} spectral {}", ray, spectral));
            tested += exact.max_component() < 0.95f && exact.max_component() > 0.02f;
        }
    }
    EXPECT_GE(tested, 6); // the rays see real attenuation, neither nothing nor everything
}

} // namespace
} // namespace illum
