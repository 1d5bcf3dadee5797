// pbrt-v4's bilinear patches: ray hits on the saddle p(u, v) = (u, v, u v) against the closed form (the
// roots of the quadratic the ray's coordinates give), the hit's uv, normals and orientation; the area
// against the integral of |∂p/∂u × ∂p/∂v|; area sampling's density against the area (E[1/p_A] = A) and
// against area_pdf(); a rectangle's spherical sampling (with and without the cosine warp) against the
// closed-form solid angle and its own pdf(); renders of a curved patch, lit and emitting, against a finely
// tessellated triangle version (means within noise); determinism across thread counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>

#include "illum/geometry/accelerator.h"
#include "illum/geometry/bilinear_patch.h"
#include "illum/image/image_io.h"
#include "illum/light/diffuse_area_light.h"
#include "illum/math/bilinear_warp.h"
#include "illum/math/rng.h"
#include "illum/math/spherical_rectangle.h"
#include "illum/math/warp.h"
#include "math/stat_util.h"
#include "test_support.h"

namespace illum {
namespace {

std::unique_ptr<BilinearPatchMesh> saddle_mesh() {
    auto m = std::make_unique<BilinearPatchMesh>();
    m->p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
    m->indices = {0, 1, 2, 3};
    m->finalize();
    return m;
}

// The nearest crossing of o + t d with z = x y over [0, 1]², from the quadratic
// dx dy t² + (ox dy + oy dx - dz) t + (ox oy - oz) = 0 (double precision).
std::optional<double> saddle_closed_form(Point3f o, Vector3f d) {
    double a = double(d.x) * d.y, b = double(o.x) * d.y + double(o.y) * d.x - d.z,
           c = double(o.x) * o.y - o.z;
    double roots[2];
    int n = 0;
    if (std::abs(a) < 1e-12) {
        roots[n++] = -c / b;
    } else {
        double disc = b * b - 4 * a * c;
        if (disc < 0) return std::nullopt;
        roots[n++] = (-b - std::sqrt(disc)) / (2 * a);
        roots[n++] = (-b + std::sqrt(disc)) / (2 * a);
    }
    std::optional<double> best;
    for (int i = 0; i < n; ++i) {
        double t = roots[i], x = o.x + t * d.x, y = o.y + t * d.y;
        if (t > 1e-4 && x >= 0 && x <= 1 && y >= 0 && y <= 1 && (!best || t < *best)) best = t;
    }
    return best;
}

TEST(BilinearPatch, SaddleHitsMatchTheClosedForm) {
    Accelerator acc;
    acc.add_patches(saddle_mesh(), nullptr, {});
    acc.commit();
    PCG32 rng(7);
    int hits = 0, misses = 0;
    for (int i = 0; i < 4000; ++i) {
        Point3f target{rng.uniform_float() * 1.4f - 0.2f, rng.uniform_float() * 1.4f - 0.2f, 0};
        target.z = target.x * target.y;
        Vector3f d = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        Point3f o = target - d * 3.0f;
        auto expected = saddle_closed_form(o, d);
        SurfaceHit hit;
        bool got = acc.intersect(Ray{o, d, kInfinity}, &hit);
        ASSERT_EQ(got, expected.has_value()) << i;
        if (!got) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_NEAR(hit.t, *expected, 2e-4) << i;
        double x = o.x + *expected * d.x, y = o.y + *expected * d.y;
        EXPECT_NEAR(hit.uv.x, x, 2e-4);
        EXPECT_NEAR(hit.uv.y, y, 2e-4);
        EXPECT_NEAR(hit.p.z, x * y, 2e-4);
        // ∂p/∂u × ∂p/∂v = (1, 0, v) × (0, 1, u) = (-v, -u, 1).
        Vector3f n = normalize(Vector3f{float(-y), float(-x), 1});
        EXPECT_GT(dot(hit.n, n), 1 - 1e-5f);
        EXPECT_EQ(hit.ns, hit.n);
        EXPECT_NEAR(dot(hit.dpdu, Vector3f{1, 0, float(y)}) / length(hit.dpdu), std::sqrt(1 + y * y), 1e-4);
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 500);
}

TEST(BilinearPatch, TextureCoordinatesNormalsAndOrientation) {
    auto m = saddle_mesh();
    m->uv = {{0.5f, 0.5f}, {1, 0.5f}, {0.5f, 2}, {1, 2}};
    // Shading normals leaning over -z: the geometric normal turns to their side.
    m->n = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {1, 1, -1}};
    Accelerator acc;
    acc.add_patches(std::move(m), nullptr, {});
    acc.commit();
    SurfaceHit hit;
    ASSERT_TRUE(acc.intersect(Ray{{0.25f, 0.75f, 5}, {0, 0, -1}}, &hit));
    float u = 0.25f, v = 0.75f;
    EXPECT_NEAR(hit.uv.x, 0.5f + 0.5f * u, 1e-5f);
    EXPECT_NEAR(hit.uv.y, 0.5f + 1.5f * v, 1e-5f);
    Vector3f ns = normalize(Vector3f{u, v, -1});
    EXPECT_NEAR(dot(hit.ns, ns), 1, 1e-5f);
    EXPECT_LT(hit.n.z, 0) << "turned to the shading normal's side";
    EXPECT_GT(dot(hit.n, normalize(Vector3f{v, u, -1})), 1 - 1e-5f);
    // ∂p/∂s = ∂p/∂u / (∂s/∂u) = (1, 0, v) / 0.5.
    EXPECT_NEAR(hit.dpdu.x, 2, 1e-4f);
    EXPECT_NEAR(hit.dpdu.z, 2 * v, 1e-4f);

    // Without normals, flip_normal reverses the geometric normal.
    auto f = saddle_mesh();
    f->flip_normal = true;
    Accelerator acc2;
    acc2.add_patches(std::move(f), nullptr, {});
    acc2.commit();
    ASSERT_TRUE(acc2.intersect(Ray{{0.25f, 0.75f, 5}, {0, 0, -1}}, &hit));
    EXPECT_GT(dot(hit.n, normalize(Vector3f{v, u, -1})), 1 - 1e-5f);
}

TEST(BilinearPatch, ShadingPartialsFollowTheWeingartenEquations) {
    auto m = saddle_mesh();
    // At (u, v): n = (-v, -u, 1) / √(1 + u² + v²); check ∂n/∂u against a central difference of n.
    float u = 0.3f, v = 0.6f, h = 1e-3f;
    ShadingPartials s = m->shading_partials(0, {u, v, 0});
    auto n_at = [](float a, float b) { return normalize(Vector3f{-b, -a, 1}); };
    Vector3f dndu = (n_at(u + h, v) - n_at(u - h, v)) / (2 * h),
             dndv = (n_at(u, v + h) - n_at(u, v - h)) / (2 * h);
    EXPECT_LT(length(Vector3f(s.dndu) - dndu), 2e-3f);
    EXPECT_LT(length(Vector3f(s.dndv) - dndv), 2e-3f);
}

// ∫∫ √(1 + u² + v²) du dv, the saddle's area, by the midpoint rule on 2000² cells (error ~1e-8).
double saddle_area() {
    const int n = 2000;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double u = (i + 0.5) / n, v = (j + 0.5) / n;
            sum += std::sqrt(1 + u * u + v * v);
        }
    return sum / (double(n) * n);
}

TEST(BilinearPatch, AreaSamplingDensityIntegratesToTheArea) {
    auto m = saddle_mesh();
    BilinearPatchShape shape(m.get(), 0);
    double area = saddle_area();
    EXPECT_NEAR(shape.area(), area, 1e-6 * area);
    test::MeanAccumulator inv_pdf, z_over_pdf;
    PCG32 rng(11);
    for (int i = 0; i < 200000; ++i) {
        AreaShapeSample s = shape.sample_area({rng.uniform_float(), rng.uniform_float()});
        ASSERT_GT(s.pdf.value, 0);
        EXPECT_NEAR(shape.area_pdf(s.p).value, s.pdf.value, 1e-4f * s.pdf.value);
        EXPECT_NEAR(s.p.z, s.p.x * s.p.y, 1e-6f);
        inv_pdf.add(1 / s.pdf.value);
        z_over_pdf.add(s.p.z / s.pdf.value);
    }
    // E[1/p_A] = A; E[z / p_A] = ∫ z dA, by the midpoint rule.
    EXPECT_NEAR(inv_pdf.mean, area, 4 * inv_pdf.std_error() + 1e-6);
    double z_integral = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double u = (i + 0.5) / n, v = (j + 0.5) / n;
            z_integral += u * v * std::sqrt(1 + u * u + v * v) / (double(n) * n);
        }
    EXPECT_NEAR(z_over_pdf.mean, z_integral, 4 * z_over_pdf.std_error() + 1e-6);
}

TEST(BilinearPatch, NonRectangularSolidAngleSamplingAgreesWithPdf) {
    auto m = saddle_mesh();
    BilinearPatchShape shape(m.get(), 0);
    ShapeSampleContext ctx{{0.3f, 0.2f, 2}, {}, {0, 0, -1}};
    PCG32 rng(5);
    for (int i = 0; i < 2000; ++i) {
        auto s = shape.sample(ctx, {rng.uniform_float(), rng.uniform_float()});
        ASSERT_TRUE(s);
        Vector3f wi = normalize(s->p - ctx.p);
        EXPECT_LT(length(s->wi - wi), 1e-6f) << "the sample's direction is the one to its point";
        float pdf = shape.pdf(ctx, wi, s->p, s->n).value;
        EXPECT_NEAR(pdf, s->pdf.value, 2e-3f * s->pdf.value);
    }
}

// The solid angle of the rectangle [0, a] × [0, b] seen from (0, 0, h): asin(a b / √((a² + h²)(b² + h²))).
double corner_solid_angle(double a, double b, double h) {
    return std::asin(a * b / std::sqrt((a * a + h * h) * (b * b + h * h)));
}

TEST(BilinearPatch, RectangleSolidAngleSampling) {
    EXPECT_NEAR(spherical_rectangle_solid_angle({0, 0, 1}, {0, 0, 0}, {2, 0, 0}, {0, 3, 0}),
                corner_solid_angle(2, 3, 1), 1e-5);
    // From below the solid angle is the same.
    EXPECT_NEAR(spherical_rectangle_solid_angle({0, 0, -1}, {0, 0, 0}, {2, 0, 0}, {0, 3, 0}),
                corner_solid_angle(2, 3, 1), 1e-5);
    auto m = std::make_unique<BilinearPatchMesh>();
    // The rectangle [-1, 2] × [-0.5, 1.5] at z = 0 (p00, p10, p01, p11).
    m->p = {{-1, -0.5f, 0}, {2, -0.5f, 0}, {-1, 1.5f, 0}, {2, 1.5f, 0}};
    m->indices = {0, 1, 2, 3};
    m->finalize();
    ASSERT_EQ(m->rectangle[0], 1);
    BilinearPatchShape shape(m.get(), 0);
    EXPECT_NEAR(shape.area(), 6, 1e-6);
    // From (0, 0, 0.7) the rectangle is four corner rectangles.
    double h = 0.7, omega = corner_solid_angle(1, 0.5, h) + corner_solid_angle(2, 0.5, h) +
                            corner_solid_angle(1, 1.5, h) + corner_solid_angle(2, 1.5, h);
    for (Normal3f n : {Normal3f{}, normalize(Normal3f{0.3f, -0.2f, -1})}) {
        ShapeSampleContext ctx{{0, 0, float(h)}, {}, n};
        test::MeanAccumulator inv_pdf;
        PCG32 rng(3);
        for (int i = 0; i < 100000; ++i) {
            Point2f u{rng.uniform_float(), rng.uniform_float()};
            auto s = shape.sample(ctx, u);
            ASSERT_TRUE(s);
            EXPECT_NEAR(s->p.z, 0, 1e-5f);
            EXPECT_GE(s->p.x, -1 - 1e-4f);
            EXPECT_LE(s->p.x, 2 + 1e-4f);
            Vector3f wi = normalize(s->p - ctx.p);
            float pdf = shape.pdf(ctx, wi, s->p, s->n).value;
            EXPECT_NEAR(pdf, s->pdf.value, 2e-3f * s->pdf.value) << u.x << " " << u.y;
            inv_pdf.add(1 / s->pdf.value);
            EXPECT_NEAR(s->n.z, 1, 1e-6f); // (p10 - p00) × (p01 - p00) is +z
        }
        EXPECT_NEAR(inv_pdf.mean, omega, 4 * inv_pdf.std_error() + 1e-6) << "n.z " << n.z;
        if (n == Normal3f{}) {
            EXPECT_NEAR(inv_pdf.std_error(), 0, 1e-4) << "uniform in solid angle";
        }
    }
}

// A saddle of size 2 (corners (±1, ±1)) tilted towards the camera, as a patch or as 2·64² triangles.
std::string saddle_shape(bool tessellated, const std::string& extra = "") {
    // p(u, v) = (2u - 1, 2v - 1, 0.8 (2u - 1)(2v - 1)); corners p00, p10, p01, p11.
    if (!tessellated)
        return "Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0.8  1 -1 -0.8  -1 1 -0.8  1 1 0.8] " + extra +
               "\n";
    const int n = 64;
    std::string p, idx;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            double x = 2.0 * i / n - 1, y = 2.0 * j / n - 1;
            p += fmt::format("{} {} {} ", x, y, 0.8 * x * y);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            idx += fmt::format("{} {} {} {} {} {} ", a, b, d, a, d, c);
        }
    return "Shape \"trianglemesh\" \"point3 P\" [" + p + "] \"integer indices\" [" + idx + "] " + extra +
           "\n";
}

std::string lit_saddle(bool tessellated) {
    return R"(LookAt 0 -3 3  0 0 0  0 0 1
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 32 "integer yresolution" 32
WorldBegin
LightSource "point" "point3 from" [1 -1 3] "rgb I" [8 8 8]
LightSource "distant" "point3 from" [-1 -2 1] "point3 to" [0 0 0] "rgb L" [0.5 0.5 0.5]
Material "diffuse" "rgb reflectance" [0.7 0.7 0.7]
)" + saddle_shape(tessellated);
}

std::string emitting_saddle(bool tessellated) {
    return R"(LookAt 0 -4 1.5  0 0 -1  0 0 1
Camera "perspective" "float fov" 50
Film "rgb" "integer xresolution" 32 "integer yresolution" 32
WorldBegin
Material "diffuse" "rgb reflectance" [0.8 0.8 0.8]
Shape "trianglemesh" "point3 P" [-4 -4 -1  4 -4 -1  4 4 -1  -4 4 -1] "integer indices" [0 1 2 0 2 3]
AttributeBegin
AreaLightSource "diffuse" "rgb L" [2 2 2] "bool twosided" true
)" + saddle_shape(tessellated) +
           "AttributeEnd\n";
}

void expect_means_agree(const std::string& a, const std::string& b, const test::RenderSetup& sa,
                        const test::RenderSetup& sb) {
    Image ia = test::render_pbrt(a, sa).image, ib = test::render_pbrt(b, sb).image;
    for (int c = 0; c < 3; ++c) {
        auto ma = test::pixel_mean(ia, c), mb = test::pixel_mean(ib, c);
        double sigma = std::hypot(ma.standard_error, mb.standard_error);
        EXPECT_NEAR(ma.mean, mb.mean, 4 * sigma) << "channel " << c;
        EXPECT_GT(ma.mean, 0.01);
    }
}

TEST(BilinearPatchRender, CurvedPatchMatchesFineTessellation) {
    test::RenderSetup a, b;
    a.spp = b.spp = 16;
    a.seed = 1;
    b.seed = 2;
    expect_means_agree(lit_saddle(false), lit_saddle(true), a, b);
}

TEST(BilinearPatchRender, CurvedEmitterMatchesFineTessellation) {
    test::RenderSetup a, b;
    a.integrator = b.integrator = "path";
    a.spp = b.spp = 32;
    a.seed = 1;
    b.seed = 2;
    expect_means_agree(emitting_saddle(false), emitting_saddle(true), a, b);
    // The emitter's area (power normalisation) is the patch's exact area.
    auto scene = build_scene(parse_pbrt_string(emitting_saddle(false), "<test>", "."));
    ASSERT_EQ(scene->lights.size(), 1u);
    auto* light = dynamic_cast<const DiffuseAreaLight*>(scene->lights.front().get());
    ASSERT_NE(light, nullptr);
    // ∫∫ |∂p/∂u × ∂p/∂v| = 4 ∫∫ √(1 + 0.64 (x² + y²)) over [-1, 1]² / 4 ... by the midpoint rule.
    double area = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            double x = 2 * (i + 0.5) / n - 1, y = 2 * (j + 0.5) / n - 1;
            area += 4 * std::sqrt(1 + 0.64 * (x * x + y * y)) / (double(n) * n);
        }
    EXPECT_NEAR(light->shape()->area(), area, 1e-5 * area);
}

// bdpt weighs the emitter's points by area_pdf() (the bilinear warp's density, not 1 / A): it must agree
// with the path tracer.
TEST(BilinearPatchRender, BidirectionalAgreesWithPathTracing) {
    test::RenderSetup a, b;
    a.integrator = "path";
    b.integrator = "bdpt";
    a.spp = b.spp = 32;
    a.seed = 3;
    b.seed = 4;
    expect_means_agree(emitting_saddle(false), emitting_saddle(false), a, b);
}

TEST(BilinearPatchRender, DeterministicAcrossThreadCounts) {
    test::RenderSetup a, b;
    a.spp = b.spp = 4;
    a.threads = 1;
    b.threads = 3;
    Image ia = test::render_pbrt(emitting_saddle(false), a).image,
          ib = test::render_pbrt(emitting_saddle(false), b).image;
    ASSERT_EQ(ia.pixel_count(), ib.pixel_count());
    for (std::size_t i = 0; i < ia.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(ia.data()[i][c], ib.data()[i][c]) << i;
}

TEST(BilinearPatch, EmissionImageSamplesItsPixels) {
    // pbrt-v4's "emissionfilename": (u, v) drawn in proportion to the pixels (row-major, v rows), so each
    // pixel's share of the samples is its weight's, the density per area is pdf(u, v) / |∂p/∂u × ∂p/∂v|
    // (E[1/p_A] = the area it reaches), and a rectangle gives up solid-angle sampling for it, its pdf()
    // agreeing.
    const float weights[] = {1, 2, 3, 4, 0, 5, 1, 8};
    const int nu = 4, nv = 2;
    auto m = std::make_unique<BilinearPatchMesh>();
    m->p = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, 0}};
    m->indices = {0, 1, 2, 3};
    m->emission_distribution = std::make_shared<const Distribution2D>(weights, nu, nv);
    m->finalize();
    BilinearPatchShape shape(m.get(), 0);
    const float total = 24;
    const int n = 200000;
    std::vector<int> counts(nu * nv, 0);
    test::MeanAccumulator inv_pdf;
    PCG32 rng(17);
    for (int i = 0; i < n; ++i) {
        AreaShapeSample s = shape.sample_area({rng.uniform_float(), rng.uniform_float()});
        ASSERT_GT(s.pdf.value, 0);
        const int iu = std::min(nu - 1, int(s.p.x / 2 * nu)), iv = std::min(nv - 1, int(s.p.y * nv));
        ++counts[iv * nu + iu];
        EXPECT_NEAR(s.pdf.value, weights[iv * nu + iu] / total * nu * nv / 2, 1e-4f * s.pdf.value);
        EXPECT_NEAR(shape.area_pdf(s.p).value, s.pdf.value, 1e-4f * s.pdf.value);
        inv_pdf.add(1 / s.pdf.value);
    }
    for (int k = 0; k < nu * nv; ++k) {
        const double p = weights[k] / total, sd = std::sqrt(n * p * (1 - p));
        EXPECT_NEAR(counts[k], n * p, 5 * sd + 0.5) << "pixel " << k;
    }
    // E[1/p_A] is the area where p_A > 0: all but the zero pixel's eighth.
    EXPECT_NEAR(inv_pdf.mean, 2 * 7.0 / 8, 4 * inv_pdf.std_error());
    ShapeSampleContext ctx{{0.5f, 0.5f, 0.3f}, {}, {0, 0, -1}};
    for (int i = 0; i < 2000; ++i) {
        auto s = shape.sample(ctx, {rng.uniform_float(), rng.uniform_float()});
        ASSERT_TRUE(s);
        float pdf = shape.pdf(ctx, normalize(s->p - ctx.p), s->p, s->n).value;
        EXPECT_NEAR(pdf, s->pdf.value, 1e-3f * s->pdf.value);
    }
}

// An emitting square (a bilinear patch without uv) whose area light reads an 8x8 image with one bright
// pixel, above a floor, rendered with and without "emissionfilename" naming the same image.
class EmissionFilename : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = std::filesystem::temp_directory_path() / ("illum_emission_" + std::to_string(::getpid()));
        std::filesystem::create_directories(root_);
        // A smooth bright spot (σ 1.5 pixels) in the image's upper right (v near 1 on the patch) over 0.5.
        Image img(16, 16);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                img.at(x, y) = Color3(
                    0.5f + 50 * std::exp(-((x - 10.5f) * (x - 10.5f) + (y - 4.5f) * (y - 4.5f)) / 4.5f));
        write_image(img, path("emit.pfm"));
    }
    void TearDown() override { std::filesystem::remove_all(root_); }
    std::string path(const std::string& name) const { return (root_ / name).string(); }
    std::string scene(const std::string& shape_extra) const {
        return fmt::format(R"(LookAt 0 -3 3  0 0 0  0 0 1
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" 24 "integer yresolution" 24
Integrator "path" "integer maxdepth" 1
WorldBegin
Material "diffuse" "rgb reflectance" [0.8 0.8 0.8]
Shape "trianglemesh" "point3 P" [-4 -4 0  4 -4 0  4 4 0  -4 4 0] "integer indices" [0 1 2 0 2 3]
AttributeBegin
AreaLightSource "diffuse" "string filename" "{}"
ReverseOrientation
Shape "bilinearmesh" "point3 P" [-1 -1 1  1 -1 1  -1 1 1  1 1 1] {}
AttributeEnd
)",
                           path("emit.pfm"), shape_extra);
    }
    std::filesystem::path root_;
};

TEST_F(EmissionFilename, KeepsTheMeanAndCutsTheNoise) {
    // Light sampling by the image is unbiased (the same means) and, with one pixel carrying most of the
    // power, far less noisy: the variance per pixel, from the difference of two seeds, drops.
    const std::string sampled = fmt::format("\"string emissionfilename\" \"{}\"", path("emit.pfm"));
    auto noise = [](const Image& a, const Image& b) {
        double sum = 0;
        for (std::size_t i = 0; i < a.pixel_count(); ++i) {
            double d = a.data()[i][1] - b.data()[i][1];
            sum += d * d / 2;
        }
        return sum / double(a.pixel_count());
    };
    test::RenderSetup s1, s2;
    s1.spp = s2.spp = 64;
    s1.seed = 1;
    s2.seed = 2;
    Image plain1 = test::render_pbrt(scene(""), s1).image, plain2 = test::render_pbrt(scene(""), s2).image;
    Image image1 = test::render_pbrt(scene(sampled), s1).image,
          image2 = test::render_pbrt(scene(sampled), s2).image;
    for (int c = 0; c < 3; ++c) {
        auto a = test::pixel_mean(plain1, c), b = test::pixel_mean(image1, c);
        EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.standard_error, b.standard_error)) << "channel " << c;
        EXPECT_GT(b.mean, 0.01);
    }
    const double plain_noise = noise(plain1, plain2), image_noise = noise(image1, image2);
    EXPECT_LT(image_noise, 0.25 * plain_noise) << plain_noise << " " << image_noise;
    std::printf("noise per pixel: %.3g without the image, %.3g with it\n", plain_noise, image_noise);
}

TEST_F(EmissionFilename, IgnoredWithUvAndAMissingFileIsReported) {
    auto with_uv = build_scene(parse_pbrt_string(
        scene(fmt::format("\"string emissionfilename\" \"{}\" \"point2 uv\" [0 0 1 0 0 1 1 1]",
                          path("emit.pfm"))),
        "<test>", "."));
    ASSERT_EQ(with_uv->warnings.size(), 1u);
    EXPECT_NE(with_uv->warnings.front().find("emissionfilename"), std::string::npos)
        << with_uv->warnings.front();
    EXPECT_THROW(
        build_scene(parse_pbrt_string(
            scene(fmt::format("\"string emissionfilename\" \"{}\"", path("none.pfm"))), "<test>", ".")),
        Error);
}

} // namespace
} // namespace illum
