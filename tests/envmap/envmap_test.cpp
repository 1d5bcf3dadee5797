// Environment-map tools: SH coefficients against closed forms, SH irradiance against brute force on a
// real map, the mirror-ball round trip, the prefilter's limits, and the path tracer against ρ/π E.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include "illum/envmap/irradiance.h"
#include "illum/envmap/prefilter.h"
#include "illum/envmap/resample.h"
#include "illum/envmap/spherical_harmonics.h"
#include "illum/image/image_io.h"
#include "test_support.h"

namespace illum {
namespace {

EnvironmentMap latlong_of(int h, auto f) {
    Image img(2 * h, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < 2 * h; ++x)
            img(x, y) = f(*env_direction(EnvLayout::LatLong, {(x + 0.5f) / (2 * h), (y + 0.5f) / h}));
    return EnvironmentMap(std::move(img), EnvLayout::LatLong);
}

void expect_sh(const SH9& sh, const std::array<double, 9>& expected, const char* what) {
    double scale = 0;
    for (double e : expected) scale = std::max(scale, std::abs(e));
    for (int i = 0; i < 9; ++i) {
        // 1e-3 relative to the coefficient, or to the largest one for coefficients that vanish.
        double tol = 1e-3 * (expected[i] != 0 ? std::abs(expected[i]) : scale);
        EXPECT_NEAR(sh.c[i][0], expected[i], tol) << what << " " << kSHNames[i];
    }
}

TEST(SphericalHarmonics, ClosedForms) {
    // Constant L = 1: L00 = 4π Y00 = 2√π; the rest vanish. Exact on both equal-area and latlong maps.
    std::array<double, 9> constant{2 * std::sqrt(kPiD), 0, 0, 0, 0, 0, 0, 0, 0};
    expect_sh(project_sh(latlong_of(256, [](Vector3f) { return Color3(1.0f); })), constant,
              "constant latlong");
    expect_sh(project_sh(EnvironmentMap(Image(256, 256, Color3(1.0f)), EnvLayout::Octahedral)), constant,
              "constant octahedral");
    // max(cos θ, 0): L00 = π Y00, L10 = 0.488603 · 2π/3, L20 = 0.315392 · π/2 (∫ (3z² - 1) z over the
    // upper hemisphere = 2π (3/4 - 1/2)); by symmetry in φ the others vanish.
    std::array<double, 9> cosine{
        0.282095 * kPiD, 0, 0.488603 * 2 * kPiD / 3, 0, 0, 0, 0.315392 * kPiD / 2, 0, 0};
    expect_sh(project_sh(latlong_of(512, [](Vector3f d) { return Color3(std::max(d.z, 0.0f)); })), cosine,
              "cosine");
    // One bright texel of power P = L Ω in direction d: L_lm = P Y_lm(d).
    const int h = 512;
    Image img(2 * h, h);
    int bx = 300, by = 170;
    img(bx, by) = Color3(1000.0f);
    double theta0 = kPiD * by / h, theta1 = kPiD * (by + 1) / h;
    double omega = 2 * kPiD / (2 * h) * (std::cos(theta0) - std::cos(theta1));
    double theta = kPiD * (by + 0.5) / h, phi = 2 * kPiD * (bx + 0.5) / (2 * h);
    Vector3f d{float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
               float(std::cos(theta))};
    auto y = sh_basis(d);
    std::array<double, 9> bright;
    for (int i = 0; i < 9; ++i) bright[i] = 1000 * omega * y[i];
    expect_sh(project_sh(EnvironmentMap(std::move(img), EnvLayout::LatLong)), bright, "one bright direction");
    // Irradiance from the constant map: E = π L everywhere; from the cosine map, E(+z) = 2π/3 exactly
    // (∫ cos² over the hemisphere), which order 2 reproduces to ~1%... checked by value: Â terms.
    SH9 c = project_sh(latlong_of(256, [](Vector3f) { return Color3(2.0f); }));
    EXPECT_NEAR(c.irradiance({0.3f, 0.4f, std::sqrt(0.75f)})[0], 2 * kPi, 2e-3);
}

// For radiance within order 2 the SH irradiance is exact: L = 1 + z + xy gives
// E(n) = π + (2π/3) n_z + (π/4) n_x n_y (the Funk-Hecke theorem with Â0, Â1, Â2); the brute force agrees.
TEST(SphericalHarmonics, IrradianceExactForOrderTwo) {
    auto map = latlong_of(256, [](Vector3f d) { return Color3(1 + d.z + d.x * d.y); });
    SH9 sh = project_sh(map);
    for (Vector3f n :
         {Vector3f{0, 0, 1}, normalize(Vector3f{1, 1, 0.2f}), normalize(Vector3f{-1, 0.3f, -2})}) {
        double exact = kPiD + 2 * kPiD / 3 * n.z + kPiD / 4 * n.x * n.y;
        EXPECT_NEAR(sh.irradiance(n)[0], exact, 1e-3 * exact);
        EXPECT_NEAR(brute_force_irradiance_at(map, n)[0], exact, 2e-3 * exact);
    }
}

// Over the sphere (solid-angle weighted): the mean absolute difference relative to the mean irradiance,
// and the mean of the per-direction relative difference |E_sh - E_bf| / E_bf.
std::pair<double, double> irradiance_differences(const EnvironmentMap& a, const EnvironmentMap& b) {
    const auto& sa = a.solid_angles();
    double abs_diff = 0, mean = 0, rel = 0, den = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            double w = sa[std::size_t(y) * a.width() + x];
            double ea = a.texel(x, y).average(), eb = b.texel(x, y).average();
            abs_diff += w * std::abs(ea - eb);
            mean += w * eb;
            rel += w * std::abs(ea - eb) / eb;
            den += w;
        }
    return {abs_diff / mean, rel / den};
}

TEST(SphericalHarmonics, IrradianceAgainstBruteForceOnRealMaps) {
    if (!test::have_shared()) GTEST_SKIP() << "no shared data";
    // The bound on mean |difference| / mean E per map. pisa and uffizi are within 3% (measured 1.85% and
    // 2.91%). grace.hdr is dominated by small, very bright windows whose irradiance has more energy above
    // order 2 than the 9 coefficients keep: measured 5.22%, a property of the truncation, not a defect;
    // 6% leaves room for the brute-force estimate's sampling and still catches a broken projection (the
    // order-0 term alone, checked below, is 10 to 25 times worse).
    struct Case {
        const char* name;
        double bound;
    };
    for (const Case& c : {Case{"grace.hdr", 0.06}, Case{"pisa.hdr", 0.03}, Case{"uffizi.hdr", 0.03}}) {
        const char* name = c.name;
        auto map = EnvironmentMap::load(test::shared_dir() + "/data/envmaps/" + name);
        SH9 coefficients = project_sh(map);
        EnvironmentMap sh = sh_irradiance_map(coefficients, EnvLayout::LatLong, 32);
        EnvironmentMap bf = brute_force_irradiance(map, EnvLayout::LatLong, 32, 64);
        auto [err, rel] = irradiance_differences(sh, bf);
        RecordProperty(fmt::format("sh_vs_bruteforce_{}", name), fmt::format("{:.4f}", err));
        std::printf("%s: SH vs brute-force irradiance: mean |difference| / mean E = %.2f%%, mean relative "
                    "difference per direction = %.2f%%\n",
                    name, 100 * err, 100 * rel);
        EXPECT_LT(err, c.bound) << name;
        // Orders 1 and 2 carry the map's directionality: without them (a constant irradiance) the
        // difference is far larger, so the bound above says something even where it is loose.
        SH9 order0 = coefficients;
        for (int i = 1; i < 9; ++i) order0.c[i] = {0, 0, 0};
        auto [err0, rel0] = irradiance_differences(sh_irradiance_map(order0, EnvLayout::LatLong, 32), bf);
        std::printf("%s: order 0 only: %.2f%%\n", name, 100 * err0);
        EXPECT_LT(err, 0.5 * err0) << name;
    }
}

TEST(Resample, MirrorBallRoundTripKeepsMeanRadiance) {
    if (!test::have_shared()) GTEST_SKIP() << "no shared data";
    auto ll = EnvironmentMap::load(test::shared_dir() + "/data/envmaps/grace.hdr");
    EnvironmentMap mb = resample(ll, EnvLayout::MirrorBall, 256);
    EnvironmentMap ll2 = resample(mb, EnvLayout::LatLong, 128);
    EnvironmentMap mb2 = resample(ll2, EnvLayout::MirrorBall, 256);
    for (int c = 0; c < 3; ++c) {
        double m0 = mb.mean_radiance()[c], m2 = mb2.mean_radiance()[c];
        std::printf("channel %d: mirror ball %.6f -> latlong %.6f -> mirror ball %.6f\n", c, m0,
                    ll2.mean_radiance()[c], m2);
        EXPECT_NEAR(m2, m0, 0.01 * m0);
        EXPECT_NEAR(m0, ll.mean_radiance()[c], 0.01 * m0);
    }
    // A mirror-ball image must be square.
    EXPECT_THROW(EnvironmentMap(Image(20, 10), EnvLayout::MirrorBall), Error);
    // The latitude-longitude map into every other layout keeps the mean within 1%.
    for (EnvLayout to :
         {EnvLayout::Octahedral, EnvLayout::Angular, EnvLayout::Cubemap, EnvLayout::MirrorBall}) {
        const EnvironmentMap& small = ll;
        EnvironmentMap o = resample(small, to, 2 * default_resample_height(small, to));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(o.mean_radiance()[c], small.mean_radiance()[c], 0.01 * small.mean_radiance()[c])
                << to_string(to);
    }
}

TEST(Prefilter, LimitsAndBrdfTable) {
    // A constant map stays constant at every roughness (the lobe's weights are normalised).
    EnvironmentMap c(Image(64, 32, Color3(0.5f)), EnvLayout::LatLong);
    PrefilterOptions opt;
    opt.height = 32;
    opt.levels = 4;
    opt.samples = 64;
    auto chain = prefilter_ggx(c, opt);
    ASSERT_EQ(chain.size(), 4u);
    for (auto& m : chain) EXPECT_NEAR(m.mean_radiance()[0], 0.5f, 1e-3);
    EXPECT_EQ(chain[1].height(), 16);
    // The BRDF table: A + B <= 1 (energy), and for a smooth surface at normal incidence A + B ~ 1.
    Image lut = brdf_lut(32, 512);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) EXPECT_LE(lut(x, y)[0] + lut(x, y)[1], 1.0f + 1e-3f);
    EXPECT_NEAR(lut(31, 0)[0] + lut(31, 0)[1], 1.0f, 0.02f);
    EXPECT_LT(lut(31, 31)[0] + lut(31, 31)[1], 0.9f); // rough surfaces lose energy (single scattering)
}

// ---- rendering under an environment map (acceptance 3 and 5) ----

struct SphereScene {
    std::string env_path;
    EnvironmentMap ll;
};

// A diffuse sphere (radius 1 at the origin, albedo ρ) under the map, seen by a tiny orthographic window
// around the point n of its surface: every pixel estimates ρ/π E(n).
std::string sphere_view(const std::string& env, Vector3f n, const std::string& sampling, double rho) {
    Point3f p{n.x, n.y, n.z}, eye{2 * n.x, 2 * n.y, 2 * n.z};
    Vector3f up = std::abs(n.z) > 0.9f ? Vector3f{1, 0, 0} : Vector3f{0, 0, 1};
    return fmt::format(R"(
Integrator "path" "integer maxdepth" [1]
LookAt {} {} {}  {} {} {}  {} {} {}
Camera "orthographic" "float screenwindow" [-0.0002 0.0002 -0.0002 0.0002]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box"
WorldBegin
LightSource "infinite" "string filename" "{}" "string sampling" "{}"
Material "diffuse" "rgb reflectance" [{} {} {}]
Shape "sphere" "float radius" 1
)",
                       eye.x, eye.y, eye.z, p.x, p.y, p.z, up.x, up.y, up.z, env, sampling, rho, rho, rho);
}

TEST(EnvRender, DiffuseSphereMatchesIrradianceAndImportanceBeatsCosine) {
    if (!test::have_shared()) GTEST_SKIP() << "no shared data";
    // A 64x32 copy of a real map (written as a PFM), so the light's bilinear radiance and the texel sum
    // of the brute-force irradiance see the same smooth function.
    auto dir = std::filesystem::temp_directory_path() / "illum_envmap_test";
    std::filesystem::create_directories(dir);
    auto full = EnvironmentMap::load(test::shared_dir() + "/data/envmaps/pisa.hdr");
    EnvironmentMap small = resample(full, EnvLayout::LatLong, 32);
    std::string path = (dir / "pisa_small.pfm").string();
    write_image(small.image(), path);
    // Bilinear lookup of the light: integrate it finely for the reference.
    EnvironmentMap fine = resample(small, EnvLayout::LatLong, 256);
    const double rho = 0.8;
    double sq_err[2] = {0, 0};
    int count = 0;
    for (Vector3f n : {Vector3f{0, 0, 1}, normalize(Vector3f{1, 1, 0.3f}),
                       normalize(Vector3f{-1, 0.2f, -0.5f}), Vector3f{0, -1, 0}}) {
        Color3 e = brute_force_irradiance_at(fine, n);
        for (int mode = 0; mode < 2; ++mode) {
            test::RenderSetup s;
            s.spp = 16;
            auto r = test::render_pbrt(sphere_view(path, n, mode == 0 ? "importance" : "none", rho), s);
            EXPECT_EQ(r.nonfinite_samples, 0u);
            for (int c = 0; c < 3; ++c) {
                double expected = rho / kPiD * e[c];
                auto m = test::pixel_mean(r.image, c);
                // 4.5 standard errors, plus 0.5% for the filtered reference's own discretisation.
                EXPECT_NEAR(m.mean, expected, 4.5 * m.standard_error + 5e-3 * expected)
                    << "n = " << n.x << " " << n.y << " " << n.z << " mode " << mode << " channel " << c;
                // Per-pixel relative RMS error at 16 spp.
                for (std::size_t i = 0; i < r.image.pixel_count(); ++i) {
                    double d = (r.image.data()[i][c] - expected) / expected;
                    sq_err[mode] += d * d;
                }
                if (mode == 0) count += int(r.image.pixel_count());
            }
        }
    }
    double rms_is = std::sqrt(sq_err[0] / count), rms_cos = std::sqrt(sq_err[1] / count);
    std::printf("relative RMS error at 16 spp: importance %.4f, cosine only %.4f (ratio %.2f)\n", rms_is,
                rms_cos, rms_cos / rms_is);
    RecordProperty("rms_importance", fmt::format("{:.4f}", rms_is));
    RecordProperty("rms_cosine", fmt::format("{:.4f}", rms_cos));
    EXPECT_LT(rms_is, rms_cos);
}

} // namespace
} // namespace illum
