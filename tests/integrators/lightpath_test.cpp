// Light tracing (render/lightpath_integrator.h) against closed forms, the path tracer and the references.
//
// Tolerances come from the noise: a mean is within 4.5 of its standard errors (measured over the pixels,
// or from two independent renders as tests/scenes/scenes_test.cpp does) of the expected value, plus a
// stated systematic bound where the comparison has one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fmt/format.h>

#include "illum/camera/camera.h"
#include "illum/image/image_io.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"
#include "illum/render/lightpath_integrator.h"
#include "illum/util/error.h"
#include "test_support.h"

namespace illum {
namespace {

constexpr double kSigmas = 4.5;

// ∫∫ W_e cos θ dω dA_lens = 1 over the film (camera_importance.h): the importance is normalised.
// Monte Carlo over the sphere of directions at the pinhole; and sample_wi's estimate of the same.
TEST(CameraImportance, PerspectiveWeIntegratesToOne) {
    Transform id;
    PerspectiveCamera cam(id, 64, 32, 50.0f);
    PCG32 rng(7);
    const int n = 400000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        Vector3f d = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        double v = cam.we(Ray{{0, 0, 0}, d, kInfinity}).value * std::max(0.0f, d.z) / uniform_sphere_pdf();
        sum += v;
        sum2 += v * v;
    }
    double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
    std::printf("perspective: ∫ W_e cos dω = %.5f +- %.5f\n", mean, se);
    EXPECT_NEAR(mean, 1.0, kSigmas * se);
    // A generated ray's direction has pdf_we().dir = W_e cos θ for a pinhole (A_lens = 1).
    auto cr = cam.generate_ray({10.3f, 20.7f}, {0.5f, 0.5f}, kDLineNm);
    ASSERT_TRUE(cr);
    Point2f raster;
    float we = cam.we(cr->ray, &raster).value;
    EXPECT_NEAR(raster.x, 10.3f, 1e-3f);
    EXPECT_NEAR(raster.y, 20.7f, 1e-3f);
    EXPECT_NEAR(cam.pdf_we(cr->ray).dir.value, we * cr->ray.d.z, 1e-4f * we);
}

TEST(CameraImportance, ThinLensSampleWiLandsWhereGenerateRayStarts) {
    Transform id;
    PerspectiveCamera cam(id, 64, 64, 40.0f, 0.1f, 3.0f);
    // A point on the plane of focus is seen at one raster position from every lens point.
    auto cr = cam.generate_ray({40.5f, 12.25f}, {0.5f, 0.5f}, kDLineNm);
    ASSERT_TRUE(cr);
    Point3f p = cr->ray.o + cr->ray.d * (3.0f / cr->ray.d.z);
    for (Point2f u : {Point2f{0.1f, 0.2f}, Point2f{0.9f, 0.6f}}) {
        auto cs = cam.sample_wi(p, u);
        ASSERT_TRUE(cs);
        EXPECT_NEAR(cs->p_raster.x, 40.5f, 1e-2f);
        EXPECT_NEAR(cs->p_raster.y, 12.25f, 1e-2f);
        EXPECT_GT(cs->we.value, 0);
    }
}

// A Lambertian plane (ρ = 0.5) lit by a point light of intensity I at height h: L(x) = ρ/π I h / d³ (d the
// distance to the light). Every pixel's expected value is that at the point its centre sees; the mean
// residual must be noise (4.5 standard errors over the pixels) within 0.2% (pixel-centre approximation).
void check_point_lit_plane(const std::string& camera, const char* what) {
    const double rho = 0.5, intensity = 3.0, h = 1.0;
    std::string scene = fmt::format(R"(
Integrator "lightpath" "integer maxdepth" [1]
LookAt 0.2 0.1 2  0.2 0.1 0  0 1 0
{}
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
PixelFilter "box"
WorldBegin
LightSource "point" "point3 from" [0 0 {}] "rgb I" [{} {} {}]
Material "diffuse" "rgb reflectance" [{} {} {}]
Shape "trianglemesh" "point3 P" [-20 -20 0 20 -20 0 20 20 0 -20 20 0] "integer indices" [0 1 2 0 2 3]
)",
                                    camera, h, intensity, intensity, intensity, rho, rho, rho);
    SceneDesc desc = parse_pbrt_string(scene, "<test>", ".");
    auto sc = build_scene(desc);
    test::RenderSetup setup;
    setup.integrator = "lightpath";
    setup.spp = 4096; // a standard error of 0.12% of the mean
    RenderResult r = test::render_pbrt(scene, setup);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    const int n = 32 * 32;
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, sum_expected = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                auto cr = sc->camera->generate_ray({x + 0.5f, y + 0.5f}, {0.5f, 0.5f}, kDLineNm);
                Point3f p = cr->ray.o + cr->ray.d * (-cr->ray.o.z / cr->ray.d.z);
                double d2 = double(p.x) * p.x + double(p.y) * p.y + h * h;
                double expected = rho / kPiD * intensity * h / (d2 * std::sqrt(d2));
                double v = r.image(x, y)[c] - expected;
                sum += v;
                sum2 += v * v;
                sum_expected += expected;
            }
        double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1)), e = sum_expected / n;
        if (c == 1)
            std::printf("%s: mean %.6f, closed form %.6f (%+.3f%%, standard error %.3f%%)\n", what, e + mean,
                        e, 100 * mean / e, 100 * se / e);
        EXPECT_LT(std::abs(mean), kSigmas * se + 2e-3 * e) << what << " channel " << c;
    }
}

TEST(LightPath, PointLitPlaneOrthographic) {
    check_point_lit_plane(R"(Camera "orthographic" "float screenwindow" [-1 1 -1 1])", "orthographic");
}
TEST(LightPath, PointLitPlanePinhole) {
    check_point_lit_plane(R"(Camera "perspective" "float fov" [60])", "pinhole");
}
TEST(LightPath, PointLitPlaneThinLens) {
    check_point_lit_plane(
        R"(Camera "perspective" "float fov" [60] "float lensradius" [0.05] "float focaldistance" [1.5])",
        "thin lens");
}

// A directly seen area light (the s = 1, t = 1 strategy): a disk of radiance L facing the camera fills
// the centre pixels with L.
TEST(LightPath, DirectlySeenAreaLight) {
    const double L = 2.0;
    std::string scene = fmt::format(R"(
LookAt 0 0 3  0 0 0  0 1 0
Camera "perspective" "float fov" [10]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box"
WorldBegin
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{} {} {}]
  Shape "disk" "float radius" [1]
AttributeEnd
)",
                                    L, L, L);
    test::RenderSetup setup;
    setup.integrator = "lightpath";
    setup.spp = 256;
    RenderResult r = test::render_pbrt(scene, setup);
    auto m = test::pixel_mean(r.image, 1);
    std::printf("directly seen light: %.5f +- %.5f, expected %.1f\n", m.mean, m.standard_error, L);
    EXPECT_NEAR(m.mean, L, kSigmas * m.standard_error + 1e-4 * L);
}

// A two-sided emitter seen from either side has radiance L: the connections from the far side start behind
// the surface they leave (from the sampled point itself, not from the photon's offset origin).
TEST(LightPath, TwoSidedAreaLightFromBothSides) {
    const double L = 1.5;
    for (const char* eye : {"0 0 3", "0 0 -3"}) {
        std::string scene = fmt::format(R"(
LookAt {}  0 0 0  0 1 0
Camera "perspective" "float fov" [10]
Film "rgb" "integer xresolution" [16] "integer yresolution" [16]
PixelFilter "box"
WorldBegin
AttributeBegin
  Material "diffuse" "rgb reflectance" [0 0 0]
  AreaLightSource "diffuse" "rgb L" [{} {} {}] "bool twosided" true
  Shape "disk" "float radius" [1]
AttributeEnd
)",
                                        eye, L, L, L);
        test::RenderSetup setup;
        setup.integrator = "lightpath";
        setup.spp = 256;
        RenderResult r = test::render_pbrt(scene, setup);
        auto m = test::pixel_mean(r.image, 1);
        std::printf("two-sided light seen from %s: %.5f +- %.5f, expected %.1f\n", eye, m.mean,
                    m.standard_error, L);
        EXPECT_NEAR(m.mean, L, kSigmas * m.standard_error + 1e-4 * L) << "eye at " << eye;
    }
}

Image render_cornell(const std::string& integrator, int spp, std::uint64_t seed, int resolution,
                     bool spectral, int threads = 0) {
    return test::render_shared_scene("cornell-box", spp, seed, resolution, spectral, integrator, threads);
}

class CornellLightPath : public testing::Test {
protected:
    void SetUp() override {
        if (!test::have_shared()) GTEST_SKIP() << "shared dir absent: " << test::shared_dir();
    }
};

// Channel means within 1% + 4.5 σ of the reference; σ of the mean of (A + B) / 2 from A - B.
void expect_means(const Image& a, const Image& b, const Image& ref, const char* what) {
    Color3 ma = a.channel_mean(), mb = b.channel_mean(), mr = ref.channel_mean();
    const std::size_t n = a.pixel_count();
    for (int c = 0; c < 3; ++c) {
        double noise = 0;
        for (std::size_t i = 0; i < n; ++i) {
            double e = a.data()[i][c] - b.data()[i][c];
            noise += 0.5 * e * e;
        }
        double sigma = std::sqrt(noise / n / (2.0 * n)) / mr[c];
        double diff = 0.5 * (ma[c] + mb[c]) / mr[c] - 1;
        std::printf("%s channel %d: mean %.6f, reference %.6f, difference %+.2f%% (noise sigma %.2f%%)\n",
                    what, c, 0.5 * (ma[c] + mb[c]), mr[c], 100 * diff, 100 * sigma);
        EXPECT_LT(std::abs(diff), 0.01 + kSigmas * sigma) << what << " channel " << c;
    }
}

TEST_F(CornellLightPath, MatchesRgbReference) {
    // The reference is 1024 x 1024: only the means are compared.
    Image ref = read_image(test::shared_dir() + "/refs/rgb/cornell-box.exr");
    Image a = render_cornell("lightpath", 16, 1, 0, false), b = render_cornell("lightpath", 16, 2, 0, false);
    expect_means(a, b, ref, "lightpath rgb");
}

TEST_F(CornellLightPath, MatchesSpectralReference) {
    Image ref = read_image(test::shared_dir() + "/refs/spectral/cornell-box.exr");
    Image a = render_cornell("lightpath", 16, 1, 0, true), b = render_cornell("lightpath", 16, 2, 0, true);
    ASSERT_EQ(a.width(), ref.width());
    expect_means(a, b, ref, "lightpath spectral");
}

// Per pixel against the path tracer at 48 x 48: d = (A - P)² - (A - B)²/2 - (P - Q)²/2 averages to zero
// when the two differ only by noise (A, B light traced; P, Q path traced; independent seeds).
TEST_F(CornellLightPath, PerPixelConsistentWithPathTracer) {
    const int res = 48;
    Image a = render_cornell("lightpath", 64, 1, res, false),
          b = render_cornell("lightpath", 64, 2, res, false);
    Image p = render_cornell("path", 64, 3, res, false), q = render_cornell("path", 64, 4, res, false);
    const std::size_t n = a.pixel_count();
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, mse = 0, noise = 0;
        for (std::size_t i = 0; i < n; ++i) {
            double ap = a.data()[i][c] - p.data()[i][c], ab = a.data()[i][c] - b.data()[i][c],
                   pq = p.data()[i][c] - q.data()[i][c];
            double d = ap * ap - 0.5 * ab * ab - 0.5 * pq * pq;
            sum += d;
            sum2 += d * d;
            mse += ap * ap;
            noise += 0.5 * ab * ab + 0.5 * pq * pq;
        }
        double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
        std::printf("channel %d: MSE(lightpath, path) / expected noise = %.3f; d = %.3g +- %.2g\n", c,
                    mse / noise, mean, se);
        EXPECT_LT(std::abs(mean), kSigmas * se) << "channel " << c;
    }
}

// 128² at 8 spp: 128 chunks, two waves (the second traced while the first is added to the film).
TEST_F(CornellLightPath, SameImageAtAnyThreadCount) {
    Image one = render_cornell("lightpath", 8, 5, 128, false, 1);
    Image two = render_cornell("lightpath", 8, 5, 128, false, 2);
    Image four = render_cornell("lightpath", 8, 5, 128, false, 4);
    ASSERT_EQ(one.pixel_count(), two.pixel_count());
    for (std::size_t i = 0; i < one.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(one.data()[i][c], two.data()[i][c]) << "pixel " << i;
            ASSERT_EQ(one.data()[i][c], four.data()[i][c]) << "pixel " << i;
        }
}

TEST(LightPath, CameraWithoutImportanceIsRejected) {
    // The check is on the interface (Camera::has_importance): the realistic camera and a thin-lens
    // orthographic one answer false; the latter needs no lens file.
    SceneDesc desc = parse_pbrt_string(R"(
Camera "orthographic" "float lensradius" [0.1]
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
LightSource "point" "point3 from" [0 0 1] "rgb I" [1 1 1]
)",
                                       "<test>", ".");
    auto scene = build_scene(desc);
    EXPECT_THROW(make_integrator("lightpath", *scene, 5), Error);
    if (!test::have_shared()) return;
    SceneDesc realistic = parse_pbrt_string(fmt::format(R"(
Camera "realistic" "string lensfile" "{}/data/lenses/dgauss-50mm.dat"
Film "rgb" "integer xresolution" [8] "integer yresolution" [8]
WorldBegin
LightSource "point" "point3 from" [0 0 1] "rgb I" [1 1 1]
)",
                                                        test::shared_dir()),
                                            "<test>", ".");
    auto scene_r = build_scene(realistic);
    EXPECT_THROW(make_integrator("lightpath", *scene_r, 5), Error);
}

} // namespace
} // namespace illum

namespace illum {
namespace {

// Shading normals make the BSDF non-symmetric (Veach 1997 §5.3): a plane whose shading normal is tilted
// by 17° from its geometric one, lit by a point light. The path tracer's estimate uses the BSDF as it is;
// light tracing must use its adjoint (the |ωo·Ns| |ωi·Ng| / (|ωo·Ng| |ωi·Ns|) factor) to see the same
// image. Means of the two within 4.5 σ (σ from the A - B differences of both).
TEST(LightPath, ShadingNormalAdjointMatchesPathTracer) {
    const std::string scene = R"(
LookAt -0.8 0.2 1.2  0 0 0  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
PixelFilter "box"
WorldBegin
LightSource "point" "point3 from" [0.6 -0.3 0.8] "rgb I" [2 2 2]
Material "diffuse" "rgb reflectance" [0.5 0.5 0.5]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
    "normal N" [0.3 0 1 0.3 0 1 0.3 0 1 0.3 0 1]
)";
    auto render_with = [&](const char* integrator, int spp, std::uint64_t seed) {
        test::RenderSetup s;
        s.integrator = integrator;
        s.max_depth = 1;
        s.spp = spp;
        s.seed = seed;
        return test::render_pbrt(scene, s).image;
    };
    Image a = render_with("lightpath", 1024, 1), b = render_with("lightpath", 1024, 2);
    Image p = render_with("path", 64, 3), q = render_with("path", 64, 4);
    const std::size_t n = a.pixel_count();
    double la = 0, pa = 0, noise = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double x = a.data()[i].g, y = b.data()[i].g, u = p.data()[i].g, v = q.data()[i].g;
        la += 0.5 * (x + y);
        pa += 0.5 * (u + v);
        // Var of each pixel's (A + B)/2 is (A - B)²/4; likewise for the path tracer.
        noise += 0.25 * (x - y) * (x - y) + 0.25 * (u - v) * (u - v);
    }
    la /= n;
    pa /= n;
    double sigma = std::sqrt(noise) / n;
    std::printf("tilted shading normal: lightpath %.6f, path %.6f (%+.3f%%, sigma %.3f%%)\n", la, pa,
                100 * (la / pa - 1), 100 * sigma / pa);
    EXPECT_LT(std::abs(la - pa), kSigmas * sigma);
}

} // namespace
} // namespace illum
