// sample_point of each grid medium at chosen points against its formula, through a transform: the
// trilinear density of "uniformgrid" (with its Lescale grid, Le and temperature emission), the RGB grids
// of "rgbgrid" in both modes, pbrt-v4's cloud density (reference values printed by pbrt-v4's own
// Noise/DNoise and CloudMedium::Density), and a NanoVDB grid written here and read back.
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include <iostream>
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include "illum/math/rng.h"
#include "illum/medium/blackbody_emission.h"
#include "illum/medium/cloud_medium.h"
#include "illum/radiometry/spectra.h"
#include "illum/radiometry/uplift.h"
#include "medium_test_util.h"

namespace illum {
namespace {

using test::DescBuilder;

std::vector<double> random_values(int n, PCG32& rng, double lo, double hi) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (double& x : v) x = lo + (hi - lo) * rng.uniform_double();
    return v;
}
std::vector<float> to_float(const std::vector<double>& v) { return {v.begin(), v.end()}; }

// Medium-space points around the box [p0, p1]: inside, on faces, at sample centres, up to half a voxel
// outside (where pbrt-v4's grids still fade out).
std::vector<Point3f> probe_points(Point3f p0, Point3f p1, PCG32& rng) {
    std::vector<Point3f> u = {{0.5f, 0.5f, 0.5f},       {0, 0.3f, 0.7f},      {1, 1, 1},
                              {0.999f, 0.01f, 0.5f},    {-0.05f, 0.5f, 0.5f}, {0.5f, 1.04f, 0.2f},
                              {1.0f / 6, 0.125f, 0.25f}};
    for (int i = 0; i < 40; ++i) u.push_back({rng.uniform_float(), rng.uniform_float(), rng.uniform_float()});
    std::vector<Point3f> m;
    for (Point3f q : u)
        m.push_back({p0.x + q.x * (p1.x - p0.x), p0.y + q.y * (p1.y - p0.y), p0.z + q.z * (p1.z - p0.z)});
    return m;
}
Point3f unit_of(Point3f m, Point3f p0, Point3f p1) {
    return {(m.x - p0.x) / (p1.x - p0.x), (m.y - p0.y) / (p1.y - p0.y), (m.z - p0.z) / (p1.z - p0.z)};
}

void expect_spectrum_near(const SampledSpectrum& a, const SampledSpectrum& b, float rel,
                          const std::string& what) {
    for (int i = 0; i < kSpectrumSamples; ++i)
        EXPECT_NEAR(a[i], b[i], rel * std::max(1.0f, std::abs(b[i]))) << what << " lane " << i;
}

TEST(UniformGrid, DensityAndLescaleGridAreTrilinearAtVoxelCentres) {
    PCG32 rng(7);
    const int nx = 3, ny = 4, nz = 2;
    std::vector<double> density = random_values(nx * ny * nz, rng, 0, 4);
    std::vector<double> lescale = random_values(nx * ny * nz, rng, 0, 2);
    Point3f p0(-1, 0.5f, 2), p1(2, 1.5f, 4);
    Transform t = test::test_transform();
    DescBuilder b("uniformgrid", t);
    b.res(nx, ny, nz).f("density", density).f("Lescale", lescale).p3("p0", p0).p3("p1", p1);
    b.rgb("sigma_a", {0.5, 1, 2}).rgb("sigma_s", {1.5, 0.25, 0}).f("scale", {2}).rgb("Le", {3, 2, 1});
    b.f("g", {0.4});
    CreatedMedium cm = b.create();
    ASSERT_TRUE(cm.medium);
    EXPECT_EQ(cm.info.type, "uniformgrid");
    EXPECT_EQ(cm.info.bytes, (2 * std::size_t(nx * ny * nz) + 16 * 16 * 16) * sizeof(float));
    EXPECT_TRUE(cm.medium->is_emissive());
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    for (Point3f m : probe_points(p0, p1, rng)) {
        Point3f u = unit_of(m, p0, p1);
        auto id = [](float v) { return v; };
        float d = test::tent_interpolate(to_float(density), nx, ny, nz, u.x, u.y, u.z, id);
        float s = test::tent_interpolate(to_float(lescale), nx, ny, nz, u.x, u.y, u.z, id);
        MediumProperties mp = cm.medium->sample_point(t(m), rgb);
        expect_spectrum_near(mp.sigma_a, SampledSpectrum(Color3(1, 2, 4)) * d, 2e-5f, "sigma_a");
        expect_spectrum_near(mp.sigma_s, SampledSpectrum(Color3(3, 0.5f, 0)) * d, 2e-5f, "sigma_s");
        expect_spectrum_near(mp.le, SampledSpectrum(Color3(3, 2, 1)) * s, 2e-5f, "Le");
        EXPECT_FLOAT_EQ(mp.phase.g, 0.4f);
    }
}

TEST(UniformGrid, LeWithoutLescaleGridIsPbrtV4sTent) {
    // pbrt-v4 stores an absent Lescale as a 1x1x1 grid of 1, which its lookup fades to 1/2 on the faces
    // and 1/8 at the corners.
    DescBuilder b("uniformgrid");
    b.f("density", {1}).rgb("Le", {2, 2, 2});
    CreatedMedium cm = b.create();
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    EXPECT_NEAR(cm.medium->sample_point({0.5f, 0.5f, 0.5f}, rgb).le[0], 2, 1e-6);
    EXPECT_NEAR(cm.medium->sample_point({0.0f, 0.5f, 0.5f}, rgb).le[0], 1, 1e-6);
    EXPECT_NEAR(cm.medium->sample_point({1.0f, 1.0f, 0.0f}, rgb).le[0], 0.25f, 1e-6);
    EXPECT_NEAR(cm.medium->sample_point({1.0f, 1.0f, 1.0f}, rgb).sigma_a[0], 0.125f, 1e-6);
}

TEST(UniformGrid, TemperatureGridEmitsThePeakNormalisedBlackbody) {
    PCG32 rng(11);
    const int nx = 2, ny = 3, nz = 2;
    std::vector<double> temp = random_values(nx * ny * nz, rng, 500, 9000);
    std::vector<double> lescale = random_values(nx * ny * nz, rng, 0.5, 2);
    Transform t = test::test_transform();
    DescBuilder b("uniformgrid", t);
    b.res(nx, ny, nz)
        .f("density", std::vector<double>(std::size_t(nx * ny * nz), 1.0))
        .f("temperature", temp);
    b.f("Lescale", lescale).f("temperaturecutoff", {300}).f("temperaturescale", {1.5});
    CreatedMedium cm = b.create();
    ASSERT_TRUE(cm.medium->is_emissive());
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    int lit = 0;
    for (Point3f m : probe_points({0, 0, 0}, {1, 1, 1}, rng)) {
        auto id = [](float v) { return v; };
        float tk = test::tent_interpolate(to_float(temp), nx, ny, nz, m.x, m.y, m.z, id);
        float s = test::tent_interpolate(to_float(lescale), nx, ny, nz, m.x, m.y, m.z, id);
        double kelvin = (double(tk) - 300) * 1.5;
        SampledSpectrum want(0.0f);
        if (kelvin > 100 && s > 0) want = SampledSpectrum(blackbody_emission_rgb_exact(kelvin)) * s;
        lit += want.max_component() > 0;
        SampledSpectrum got = cm.medium->sample_point(t(m), rgb).le;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-3f * std::abs(want[c]) + 1e-7f) << kelvin;
        // Spectral mode: Planck's law over its peak at the four wavelengths.
        SampledWavelengths w = test::spectral_wavelengths(rng.uniform_float());
        SampledSpectrum gs = cm.medium->sample_point(t(m), w).le;
        for (int i = 0; i < kSpectrumSamples; ++i) {
            float ws = kelvin > 100 ? float(blackbody_normalized(w.lambda[i], kelvin)) * s : 0.0f;
            EXPECT_NEAR(gs[i], ws, 1e-4f * ws + 1e-7f);
        }
    }
    EXPECT_GT(lit, 20);
}

TEST(BlackbodyEmission, RgbTableIsWithinATenthOfAPercentAbove800K) {
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    for (double t = 800; t < 2e5; t *= 1.0137) {
        Color3 exact = blackbody_emission_rgb_exact(t);
        SampledSpectrum got = blackbody_emission(float(t), rgb);
        float m = std::max({std::abs(exact.r), std::abs(exact.g), std::abs(exact.b)});
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], exact[c], 1e-3f * m) << t;
    }
    EXPECT_EQ(blackbody_emission(100, rgb).max_component(), 0);
    EXPECT_GT(blackbody_emission(1000, rgb).max_component(), 0);
}

TEST(UniformGrid, SpectralCoefficientsAreTheUpliftedRgbTimesDensity) {
    DescBuilder b("uniformgrid");
    b.res(2, 1, 1).f("density", {1, 3}).rgb("sigma_a", {0.2, 0.5, 0.9}).rgb("sigma_s", {1, 1, 1});
    CreatedMedium cm = b.create();
    SampledWavelengths w = test::spectral_wavelengths(0.37f);
    MediumProperties mp = cm.medium->sample_point({0.75f, 0.5f, 0.5f}, w);
    expect_spectrum_near(mp.sigma_a, uplift_unbounded(Color3(0.2f, 0.5f, 0.9f), w) * 3, 1e-5f, "sigma_a");
    expect_spectrum_near(mp.sigma_s, SampledSpectrum(3.0f), 1e-5f, "sigma_s");
}

TEST(RGBGrid, CoefficientsAndEmissionInterpolateSamplesInBothModes) {
    PCG32 rng(5);
    const int nx = 2, ny = 3, nz = 3, n = nx * ny * nz;
    std::vector<double> sa = random_values(3 * n, rng, 0, 2), ss = random_values(3 * n, rng, 0, 3),
                        le = random_values(3 * n, rng, 0, 5);
    auto colors = [](const std::vector<double>& v) {
        std::vector<Color3> c;
        for (std::size_t i = 0; i < v.size(); i += 3)
            c.push_back(Color3(float(v[i]), float(v[i + 1]), float(v[i + 2])));
        return c;
    };
    Point3f p0(0, -2, 1), p1(1, 2, 1.5f);
    Transform t = test::test_transform();
    DescBuilder b("rgbgrid", t);
    b.res(nx, ny, nz).rgb("sigma_a", sa).rgb("sigma_s", ss).rgb("Le", le).p3("p0", p0).p3("p1", p1);
    b.f("scale", {1.5}).f("Lescale", {0.5}).f("g", {-0.3});
    CreatedMedium cm = b.create();
    ASSERT_TRUE(cm.medium->is_emissive());
    EXPECT_EQ(cm.info.bytes, 3 * std::size_t(n) * sizeof(Color3) + 16 * 16 * 16 * sizeof(float));
    for (Point3f m : probe_points(p0, p1, rng)) {
        Point3f u = unit_of(m, p0, p1);
        SampledWavelengths rgb = SampledWavelengths::rgb_mode();
        auto as_rgb = [](Color3 c) { return SampledSpectrum(c); };
        MediumProperties mp = cm.medium->sample_point(t(m), rgb);
        expect_spectrum_near(mp.sigma_a,
                             test::tent_interpolate(colors(sa), nx, ny, nz, u.x, u.y, u.z, as_rgb) * 1.5f,
                             2e-5f, "sigma_a");
        expect_spectrum_near(mp.sigma_s,
                             test::tent_interpolate(colors(ss), nx, ny, nz, u.x, u.y, u.z, as_rgb) * 1.5f,
                             2e-5f, "sigma_s");
        expect_spectrum_near(
            mp.le, test::tent_interpolate(colors(le), nx, ny, nz, u.x, u.y, u.z, as_rgb) * 0.5f, 2e-5f, "Le");
        // Spectral: the samples' spectra interpolated (pbrt-v4 RGBUnboundedSpectrum / RGBIlluminantSpectrum).
        SampledWavelengths w = test::spectral_wavelengths(rng.uniform_float());
        auto unb = [&](Color3 c) { return uplift_unbounded(c, w); };
        auto ill = [&](Color3 c) { return uplift_illuminant(c, w); };
        MediumProperties ms = cm.medium->sample_point(t(m), w);
        expect_spectrum_near(ms.sigma_a,
                             test::tent_interpolate(colors(sa), nx, ny, nz, u.x, u.y, u.z, unb) * 1.5f, 1e-4f,
                             "spectral sigma_a");
        expect_spectrum_near(ms.sigma_s,
                             test::tent_interpolate(colors(ss), nx, ny, nz, u.x, u.y, u.z, unb) * 1.5f, 1e-4f,
                             "spectral sigma_s");
        expect_spectrum_near(ms.le, test::tent_interpolate(colors(le), nx, ny, nz, u.x, u.y, u.z, ill) * 0.5f,
                             1e-4f, "spectral Le");
    }
}

TEST(RGBGrid, AMissingCoefficientGridIsOneTimesScale) {
    DescBuilder b("rgbgrid");
    b.rgb("sigma_s", {0.5, 1, 2}).f("scale", {3});
    CreatedMedium cm = b.create();
    EXPECT_FALSE(cm.medium->is_emissive());
    MediumProperties mp = cm.medium->sample_point({0.5f, 0.5f, 0.5f}, SampledWavelengths::rgb_mode());
    expect_spectrum_near(mp.sigma_a, SampledSpectrum(3.0f), 1e-6f, "sigma_a");
    expect_spectrum_near(mp.sigma_s, SampledSpectrum(Color3(1.5f, 3, 6)), 1e-6f, "sigma_s");
}

// Printed by pbrt-v4 (util/noise.cpp and CloudMedium::Density of media.h, compiled from its source):
// point p, Noise(3p), DNoise(3p), Density(p) with (density 1, wispiness 1, frequency 5) and with
// (density 2.5, wispiness 0, frequency 3).
struct CloudReference {
    float x, y, z, noise, gx, gy, gz, d1, d2;
};
constexpr CloudReference kCloud[] = {
    {0.13f, 0.71f, 0.37f, 0.553758264f, 0.781834126f, 0.571811199f, -0.38574934f, 0.336304039f, 0.800156236f},
    {0.5f, 0.55f, 0.5f, -0.60516417f, -0.803029537f, 0.374484062f, 1.2580514f, 0.241607994f, 0},
    {0.9f, 0.8f, 0.1f, -0.0375240743f, 0.988676608f, 1.15321732f, 0.10805279f, 0.0356077068f, 0.149536207f},
    {-0.3f, 0.62f, 1.7f, 0.188968554f, 1.08748674f, 0.376543403f, 1.1269331f, 0, 0.820028067f},
    {2.5f, 0.95f, -1.25f, 0.103405669f, 0.164823979f, 0.626140833f, -0.515265048f, 0.0465992019f, 0},
    {0.25f, 0.3f, 0.75f, -0.314221412f, -0.0218749046f, 0.521886349f, -0.749793649f, 0.654219866f,
     0.399999976f},
};

TEST(Cloud, NoiseAndDensityMatchPbrtV4) {
    for (const CloudReference& r : kCloud) {
        Point3f p(r.x * 3, r.y * 3, r.z * 3);
        EXPECT_NEAR(perlin_noise(p), r.noise, 2e-6f);
        Vector3f g = perlin_noise_gradient(p);
        // A forward difference of step 0.01 magnifies the last bits of the noise by 100.
        EXPECT_NEAR(g.x, r.gx, 2e-4f);
        EXPECT_NEAR(g.y, r.gy, 2e-4f);
        EXPECT_NEAR(g.z, r.gz, 2e-4f);
    }
    Transform t = test::test_transform();
    DescBuilder b1("cloud", t), b2("cloud", t);
    b1.rgb("sigma_s", {2, 2, 2}).rgb("sigma_a", {0.5, 1, 0}).p3("p0", {-1, 0, -2}).p3("p1", {3, 1, 2});
    b2.f("density", {2.5}).f("wispiness", {0}).f("frequency", {3}).rgb("sigma_s", {1, 1, 1});
    CreatedMedium c1 = b1.create(), c2 = b2.create();
    EXPECT_EQ(c1.info.type, "cloud");
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    for (const CloudReference& r : kCloud) {
        Point3f m(r.x, r.y, r.z);
        MediumProperties mp = c1.medium->sample_point(t(m), rgb);
        EXPECT_NEAR(mp.sigma_s[0] / 2, r.d1, 1e-4f) << m.x;
        EXPECT_NEAR(mp.sigma_a[1], r.d1, 1e-4f);
        EXPECT_EQ(mp.sigma_a[2], 0);
        EXPECT_NEAR(c2.medium->sample_point(t(m), rgb).sigma_s[0], r.d2, 1e-4f) << m.x;
    }
}

TEST(Cloud, MajorantIsSigmaTInsideTheBox) {
    DescBuilder b("cloud");
    b.rgb("sigma_a", {1, 2, 3}).rgb("sigma_s", {0.5, 0.5, 0.5}).p3("p0", {0, 0, 0}).p3("p1", {2, 1, 1});
    CreatedMedium cm = b.create();
    Ray r{{-1, 0.5f, 0.5f}, {1, 0, 0}};
    MajorantIterator it = cm.medium->sample_ray(r, 10, SampledWavelengths::rgb_mode());
    std::optional<MajorantSegment> s = it.next();
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->t0, 1, 1e-5f);
    EXPECT_NEAR(s->t1, 3, 1e-5f);
    EXPECT_FLOAT_EQ(s->sigma_maj[2], 3.5f);
    EXPECT_FALSE(it.next());
}

// A small NanoVDB file: float grid "density" over index box [lo, lo + n) and optionally "temperature",
// voxel size h, origin o; values from f(i, j, k).
struct VdbFile {
    std::string path;
    ~VdbFile() { std::filesystem::remove(path); }
};

template <class F>
nanovdb::GridHandle<nanovdb::HostBuffer> make_grid(const std::string& name, nanovdb::Coord lo,
                                                   nanovdb::Coord n, double h, nanovdb::Vec3d o, F f) {
    nanovdb::GridBuilder<float> builder(0.0f, nanovdb::GridClass::FogVolume);
    auto acc = builder.getAccessor();
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
                nanovdb::Coord c(lo[0] + i, lo[1] + j, lo[2] + k);
                acc.setValue(c, f(c[0], c[1], c[2]));
            }
    return builder.getHandle<>(h, o, name);
}

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()) + ".nvdb"))
        .string();
}

TEST(NanoVDB, DensityAndTemperatureReadBackTrilinearInIndexSpace) {
    nanovdb::Coord lo(-2, 1, 0), n(5, 4, 6);
    const double h = 0.25;
    const nanovdb::Vec3d origin(0.3, -0.2, 0.1);
    auto dens = [](int i, int j, int k) { return 0.1f + float((i * 7 + j * 13 + k * 5 + 40) % 11) / 4; };
    auto temp = [](int i, int j, int k) { return 1500.0f + 200.0f * float(i + 2 * j - k); };
    VdbFile file{temp_path("illum-medium-test")};
    {
        std::vector<nanovdb::GridHandle<nanovdb::HostBuffer>> handles;
        handles.push_back(make_grid("density", lo, n, h, origin, dens));
        handles.push_back(make_grid("temperature", lo, n, h, origin, temp));
        nanovdb::io::writeGrids(file.path, handles);
    }
    Transform t = test::test_transform();
    DescBuilder b("nanovdb", t);
    b.s("filename", file.path).rgb("sigma_a", {1, 2, 3}).rgb("sigma_s", {0.5, 0.5, 0.5}).f("scale", {2});
    b.f("Lescale", {3}).f("temperatureoffset", {200}).f("temperaturescale", {1.25});
    CreatedMedium cm = b.create();
    ASSERT_TRUE(cm.medium);
    EXPECT_EQ(cm.info.type, "nanovdb");
    EXPECT_GT(cm.info.bytes, 64u * 64 * 64 * sizeof(float));
    EXPECT_TRUE(cm.medium->is_emissive());
    // The values sit at integer index points; index = (medium point - origin) / h.
    auto interpolate = [&](auto f, double x, double y, double z) {
        double sum = 0;
        auto tent = [](double v) { return std::max(0.0, 1 - std::abs(v)); };
        for (int k = lo[2]; k < lo[2] + n[2]; ++k)
            for (int j = lo[1]; j < lo[1] + n[1]; ++j)
                for (int i = lo[0]; i < lo[0] + n[0]; ++i)
                    sum += f(i, j, k) * tent(x - i) * tent(y - j) * tent(z - k);
        return sum;
    };
    PCG32 rng(3);
    SampledWavelengths rgb = SampledWavelengths::rgb_mode();
    for (int s = 0; s < 60; ++s) {
        // Index points over the active box and a voxel beyond it.
        double x = lo[0] - 1 + (n[0] + 1.5) * rng.uniform_double(),
               y = lo[1] - 1 + (n[1] + 1.5) * rng.uniform_double(),
               z = lo[2] - 1 + (n[2] + 1.5) * rng.uniform_double();
        Point3f m(float(origin[0] + h * x), float(origin[1] + h * y), float(origin[2] + h * z));
        double d = interpolate(dens, x, y, z);
        MediumProperties mp = cm.medium->sample_point(t(m), rgb);
        EXPECT_NEAR(mp.sigma_a[1], 4 * d, 2e-4 * std::max(1.0, d)) << x << " " << y << " " << z;
        EXPECT_NEAR(mp.sigma_s[0], 1 * d, 2e-4 * std::max(1.0, d));
        double kelvin = (interpolate(temp, x, y, z) - 200) * 1.25;
        Color3 want = kelvin > 100 ? blackbody_emission_rgb_exact(kelvin) * 3 : Color3(0.0f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mp.le[c], want[c], 3e-3 * std::abs(want[c]) + 1e-6) << kelvin;
    }
    // The bounds are the grid's world box: a ray along x through its middle meets it from index lo to
    // lo + n, and every segment's majorant covers the density there.
    Point3f mid(float(origin[0] + h * (lo[0] + n[0] / 2.0)), float(origin[1] + h * (lo[1] + n[1] / 2.0)),
                float(origin[2] + h * (lo[2] + n[2] / 2.0)));
    Point3f start(mid.x - 10, mid.y, mid.z);
    Vector3f dir = t(Vector3f(1, 0, 0));
    Ray r{t(start), dir / length(dir)};
    float unit = length(dir); // world t per medium-space unit
    MajorantIterator it = cm.medium->sample_ray(r, 100, rgb);
    std::optional<MajorantSegment> first = it.next(), last = first;
    ASSERT_TRUE(first);
    while (auto s = it.next()) last = s;
    double x0 = origin[0] + h * lo[0], x1 = origin[0] + h * (lo[0] + n[0]);
    EXPECT_NEAR(first->t0 / unit, x0 - start.x, 1e-3);
    EXPECT_NEAR(last->t1 / unit, x1 - start.x, 1e-3);
}

TEST(NanoVDB, AFileWithoutTemperatureIsNotEmissive) {
    VdbFile file{temp_path("illum-medium-test-d")};
    nanovdb::io::writeGrid(file.path, make_grid("density", {0, 0, 0}, {3, 3, 3}, 1, {0, 0, 0},
                                                [](int, int, int) { return 0.5f; }));
    DescBuilder b("nanovdb");
    b.s("filename", file.path);
    CreatedMedium cm = b.create();
    EXPECT_FALSE(cm.medium->is_emissive());
    // Index point (1, 1, 1) is inside the constant block.
    EXPECT_NEAR(cm.medium->sample_point({1, 1, 1}, SampledWavelengths::rgb_mode()).sigma_a[0], 0.5f, 1e-6f);
}

} // namespace
} // namespace illum
