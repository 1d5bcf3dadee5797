// pbrt-v4's "measured" BRDF (bsdf/measured.h) on RGL `.bsdf` files made from an analytic GGX conductor
// (bsdf/rgl_tabulate.h), since no measured file is available offline: the file round-trips; the model
// reproduces the analytic BRDF exactly at the tables' nodes and within the interpolation error elsewhere
// (an error that shrinks as the tables get finer), in RGB and spectral modes; it is nearly reciprocal,
// conserves energy, and its pdf integrates to the fraction of samples it returns. Broken files give
// errors naming the file. (The registry's audit runs the chi-square test on `synthetic:` tables.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/measured.h"
#include "illum/bsdf/rgl_tabulate.h"
#include "illum/math/warp.h"
#include "illum/radiometry/color_space.h"
#include "illum/util/error.h"

namespace illum {
namespace {

std::string temp_path(const char* name) { return ::testing::TempDir() + name; }

constexpr float kAlpha = 0.3f;
float grey(float) { return 0.8f; }
float falling(float l) { return 0.9f - 0.5f * (l - 360) / 470; }

RglBrdf tabulate(int grid, int theta_nodes, std::vector<float> wavelengths, float (*r)(float)) {
    RglTabulation t;
    t.grid = grid;
    t.theta_nodes = theta_nodes;
    t.wavelengths = std::move(wavelengths);
    return RglBrdf::from_tensor(tabulate_rgl(MicrofacetDistribution(MicrofacetType::GGX, kAlpha, kAlpha),
                                             ggx_conductor_brdf(kAlpha, r), t),
                                "test");
}

// Mean over random direction pairs (cos-weighted, both above 0.1) of |measured - analytic| / mean analytic,
// at wavelength `lambda` (spectral mode) or in RGB (lambda 0, grey reflectance).
double relative_error(const RglBrdf& data, float (*r)(float), float lambda, int pairs = 20000) {
    SampledWavelengths w;
    if (lambda > 0) {
        w.color_space = &RGBColorSpace::srgb();
        for (float& l : w.lambda) l = lambda;
    }
    MeasuredBxDF m(&data, lambda > 0 ? &w : nullptr);
    SpectralBrdf f = ggx_conductor_brdf(kAlpha, r);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> U(0, 0.999f);
    double err = 0, ref = 0;
    for (int i = 0; i < pairs; ++i) {
        Vector3f wo = sample_uniform_hemisphere({U(rng), U(rng)}),
                 wi = sample_uniform_hemisphere({U(rng), U(rng)});
        if (wo.z < 0.1f || wi.z < 0.1f) continue;
        double a = f(wo, wi, lambda > 0 ? lambda : 550), b = m.f(wo, wi, TransportMode::Radiance)[1];
        err += std::abs(a - b) * wi.z;
        ref += a * wi.z;
    }
    return err / ref;
}

TEST(Measured, TensorFileRoundTrip) {
    RglTabulation t;
    t.grid = 8;
    t.theta_nodes = 4;
    TensorFile file = tabulate_rgl(MicrofacetDistribution(MicrofacetType::GGX, 0.3f, 0.3f),
                                   ggx_conductor_brdf(0.3f, grey), t);
    std::string path = temp_path("roundtrip.bsdf");
    file.write(path);
    TensorFile back = TensorFile::read(path);
    ASSERT_EQ(back.fields.size(), file.fields.size());
    for (const auto& [name, f] : file.fields) {
        const TensorField* g = back.find(name);
        ASSERT_NE(g, nullptr) << name;
        EXPECT_EQ(g->type, f.type) << name;
        EXPECT_EQ(g->shape, f.shape) << name;
        EXPECT_EQ(g->bytes, f.bytes) << name;
    }
    EXPECT_EQ(back.find("spectra")->shape, (std::vector<std::uint64_t>{1, 4, 2, 8, 8}));
    RglBrdf b = *RglBrdf::read(path);
    EXPECT_TRUE(b.isotropic);
    EXPECT_TRUE(b.spectral());
    EXPECT_EQ(b.description, t.description);
    std::remove(path.c_str());
}

TEST(Measured, ExactAtTheNodes) {
    // wo at a θ node and wi = reflect(wo, vndf(s)) for s at a node of the vndf's input square: the
    // interpolation is exact there, so the model returns the analytic value up to float rounding.
    RglBrdf data = tabulate(32, 16, {360, 830}, grey);
    MeasuredBxDF m(&data, nullptr);
    SpectralBrdf f = ggx_conductor_brdf(kAlpha, grey);
    int checked = 0;
    for (int i = 1; i < 14; i += 3) {
        float th = rgl_u_to_theta(i / 15.0f), params[2] = {0, th};
        Vector3f wo(std::sin(th), 0, std::cos(th));
        for (int y = 1; y < 31; y += 4)
            for (int x = 1; x < 31; x += 4) {
                Point2f um = data.vndf.sample({x / 31.0f, y / 31.0f}, params).p;
                float tm = rgl_u_to_theta(um.x);
                Vector3f mm = spherical_direction(std::sin(tm), std::cos(tm), rgl_u_to_phi(um.y));
                Vector3f wi = reflect(wo, mm);
                if (wi.z < 0.05f) continue;
                double a = f(wo, wi, 550), b = m.f(wo, wi, TransportMode::Radiance)[0];
                EXPECT_NEAR(b, a, 2e-3 * a + 1e-5) << "θo " << th << " node " << x << "," << y;
                ++checked;
            }
    }
    EXPECT_GT(checked, 200);
}

TEST(Measured, MatchesTheAnalyticBrdfWithinTheInterpolationError) {
    // RGB mode (grey reflectance): the error falls as the tables get finer (bilinear: 4x per halving of
    // the spacing), and is below 1% at the RGL database's 32² grid.
    double e16 = relative_error(tabulate(16, 8, {360, 830}, grey), grey, 0);
    double e32 = relative_error(tabulate(32, 16, {360, 830}, grey), grey, 0);
    double e64 = relative_error(tabulate(64, 32, {360, 830}, grey), grey, 0);
    std::printf("mean relative error of f: 16² %.4f, 32² %.4f, 64² %.4f\n", e16, e32, e64);
    EXPECT_LT(e32, 0.35 * e16);
    EXPECT_LT(e64, 0.35 * e32);
    EXPECT_LT(e32, 0.01);
    // Spectral mode: the spectra interpolated at λ between the wavelength nodes (r is linear in λ, the
    // Fresnel term not quite, so nodes every 94 nm leave a small error at 500 nm).
    RglBrdf spectral = tabulate(32, 16, {360, 454, 548, 642, 736, 830}, falling);
    for (float lambda : {400.0f, 500.0f, 700.0f}) {
        double e = relative_error(spectral, falling, lambda);
        std::printf("spectral, %.0f nm: mean relative error %.4f\n", lambda, e);
        EXPECT_LT(e, e32 + 0.01) << lambda;
    }
}

TEST(Measured, SpectralTableReducesToItsRgb) {
    // RGB mode of a spectral file: a grey spectrum gives equal channels, equal to the spectral value.
    RglBrdf data = tabulate(16, 8, {360, 600, 830}, grey);
    MeasuredBxDF m(&data, nullptr);
    SampledWavelengths w;
    w.color_space = &RGBColorSpace::srgb();
    for (float& l : w.lambda) l = 555;
    MeasuredBxDF ms(&data, &w);
    Vector3f wo = normalize(Vector3f(0.3f, 0.1f, 0.9f)), wi = normalize(Vector3f(-0.4f, 0.2f, 0.8f));
    SampledSpectrum rgb = m.f(wo, wi, TransportMode::Radiance).s,
                    sp = ms.f(wo, wi, TransportMode::Radiance).s;
    EXPECT_NEAR(rgb[0], rgb[1], 1e-3f * rgb[1]);
    EXPECT_NEAR(rgb[2], rgb[1], 1e-3f * rgb[1]);
    EXPECT_NEAR(sp[0], rgb[1], 2e-3f * rgb[1]);
}

TEST(Measured, ReciprocalEnergyConservingAndNormalised) {
    RglBrdf data = tabulate(32, 16, {360, 830}, grey);
    MeasuredBxDF m(&data, nullptr);
    // Reciprocity holds for the analytic BRDF; the tables keep it within their interpolation error.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<float> U(0, 0.999f);
    double diff = 0, sum = 0;
    for (int i = 0; i < 20000; ++i) {
        Vector3f a = sample_uniform_hemisphere({U(rng), U(rng)}),
                 b = sample_uniform_hemisphere({U(rng), U(rng)});
        if (a.z < 0.1f || b.z < 0.1f) continue;
        float fab = m.f(a, b, TransportMode::Radiance)[1], fba = m.f(b, a, TransportMode::Radiance)[1];
        diff += std::abs(fab - fba) * a.z * b.z;
        sum += 0.5 * (fab + fba) * a.z * b.z;
    }
    std::printf("mean reciprocity difference %.4f\n", diff / sum);
    EXPECT_LT(diff / sum, 0.01);
    SpectralBrdf f = ggx_conductor_brdf(kAlpha, grey);
    for (double t : {0.0, 30.0, 60.0, 80.0}) {
        Vector3f wo = direction_deg(t, 40);
        // Albedo <= 1, and equal to the analytic model's within 1%.
        Rgb64 a = albedo_quadrature(m, wo, 256, true);
        double analytic = 0;
        const int n = 256;
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < 2 * n; ++k) {
                double th = (j + 0.5) * kPi / 2 / n, ph = (k + 0.5) * kPi / n;
                Vector3f wi = spherical_direction(float(std::sin(th)), float(std::cos(th)), float(ph));
                analytic += f(wo, wi, 550) * std::cos(th) * std::sin(th) * (kPi / 2 / n) * (kPi / n);
            }
        std::printf("θo %.0f: albedo measured %.4f analytic %.4f\n", t, a[1], analytic);
        EXPECT_LE(a[1], 1.0) << t;
        EXPECT_NEAR(a[1], analytic, 0.01 * analytic + 0.003) << t;
        // ∫ pdf dω is the probability that sample() returns a direction (some warped normals reflect wo
        // below the horizon); Monte Carlo counts it.
        double pdf_sum = 0;
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < 2 * n; ++k) {
                double th = (j + 0.5) * kPi / 2 / n, ph = (k + 0.5) * kPi / n;
                Vector3f wi = spherical_direction(float(std::sin(th)), float(std::cos(th)), float(ph));
                pdf_sum +=
                    m.pdf(wo, wi, TransportMode::Radiance).value * std::sin(th) * (kPi / 2 / n) * (kPi / n);
            }
        int ok = 0;
        const int samples = 40000;
        for (int s = 0; s < samples; ++s)
            ok += m.sample(wo, 0.5f, {U(rng), U(rng)}, TransportMode::Radiance) ? 1 : 0;
        double p = double(ok) / samples, se = std::sqrt(p * (1 - p) / samples);
        std::printf("θo %.0f: ∫ pdf dω %.4f, fraction of samples returned %.4f ± %.4f\n", t, pdf_sum, p, se);
        EXPECT_NEAR(pdf_sum, p, 4 * se + 0.005) << t;
        EXPECT_LE(pdf_sum, 1.005) << t;
        if (t <= 60) {
            EXPECT_GT(pdf_sum, 0.97) << t;
        }
    }
}

TEST(Measured, BrokenFilesGiveErrorsNamingTheFile) {
    std::string path = temp_path("broken.bsdf");
    auto expect = [&](const std::string& needle) {
        try {
            RglBrdf::read(path);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("broken.bsdf"), std::string::npos) << e.what();
        }
    };
    std::ofstream(path, std::ios::binary) << "not a tensor";
    expect("tensor_file");
    RglTabulation t;
    t.grid = 4;
    t.theta_nodes = 3;
    TensorFile file = tabulate_rgl(MicrofacetDistribution(MicrofacetType::GGX, 0.3f, 0.3f),
                                   ggx_conductor_brdf(0.3f, grey), t);
    file.write(path);
    {
        std::ifstream in(path, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() - 100);
    }
    expect("truncated");
    TensorFile missing = file;
    missing.fields.erase("sigma");
    missing.write(path);
    expect("no field \"sigma\"");
    TensorFile wrong = file;
    wrong.fields["vndf"] = TensorField::floats({1, 2, 4, 4}, std::vector<float>(32, 1.0f));
    wrong.write(path);
    expect("shapes do not fit");
    std::remove(path.c_str());
}

} // namespace
} // namespace illum
