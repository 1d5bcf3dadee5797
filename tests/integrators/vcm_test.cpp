// Vertex connection and merging (render/vcm_integrator.h): its MIS weights sum to one over every technique
// of a path (random densities); a closed furnace in each mode; its modes (connections only, merging only)
// agree with the full estimator and with the path tracer per pixel up to noise; the image does not depend on
// the thread count; the Cornell box's means match the references. Tolerances are 4.5 standard errors
// measured over the pixels at fixed seeds (bdpt_test.cpp's convention).
#include <algorithm>
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "illum/image/image_io.h"
#include "illum/math/rng.h"
#include "illum/render/light_vertex_grid.h"
#include "illum/render/vcm_integrator.h"
#include "illum/render/vcm_mis.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "illum/util/error.h"
#include "test_support.h"

namespace illum {
namespace {

using test::pixel_mean;
using test::render_pbrt;
using test::RenderSetup;

constexpr double kSigmas = 4.5;

// A path x_0 (light) .. x_k (camera) with its densities from both sides and its vertices' kinds.
struct SyntheticPath {
    int k = 0;
    std::vector<float> fwd, rev; // p→(x_i), p←(x_i)
    std::vector<bool> delta, nonspecular;
    bool light_delta = false;
};

// Technique weights of one path: VC(s) for s = 0..k (t = k + 1 - s >= 1) and VM(j) for j = 1..k-1, each
// evaluated from the subpaths it would join, as the integrator does.
double weight_total(const SyntheticPath& p, const MisTechniques& m, int* techniques) {
    const int k = p.k;
    auto light_side = [&](int n) {
        std::vector<MisVertex> v(std::size_t(std::max(n, 1)));
        for (int i = 0; i < n; ++i)
            v[std::size_t(i)] = {p.fwd[std::size_t(i)], p.rev[std::size_t(i)], p.delta[std::size_t(i)],
                                 p.nonspecular[std::size_t(i)]};
        return v;
    };
    auto camera_side = [&](int n) { // x_k .. x_{k-n+1}
        std::vector<MisVertex> v(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            std::size_t x = std::size_t(k - i);
            v[std::size_t(i)] = {p.rev[x], p.fwd[x], p.delta[x], p.nonspecular[x]};
        }
        return v;
    };
    double total = 0;
    *techniques = 0;
    for (int s = 0; s <= k; ++s) {
        const int t = k + 1 - s;
        if (s == 1 && t == 1) continue;
        if ((s > 0 && p.delta[std::size_t(s - 1)]) || p.delta[std::size_t(s)]) continue; // joint on a delta
        if (s == 0 && p.light_delta) continue;
        auto lv = light_side(s);
        auto cv = camera_side(t);
        float sum = technique_sum(lv.data(), s, cv.data(), t, p.light_delta, m);
        float term = connection_term(lv.data(), s, cv.data(), t, m);
        // The running sums give the same total.
        std::vector<float> lt(lv.size()), ct(cv.size());
        subpath_tails(lv.data(), s, false, p.light_delta, m, lt.data());
        subpath_tails(cv.data(), t, true, false, m, ct.data());
        float sum_tails = technique_sum(lv.data(), s, cv.data(), t, p.light_delta, m, lt.data(), ct.data());
        EXPECT_NEAR(sum_tails, sum, 1e-5f * sum);
        if (term > 0) ++*techniques;
        if (sum > 0) total += term / sum;
    }
    for (int j = 1; m.vm && j <= k - 1; ++j) {
        if (!p.nonspecular[std::size_t(j)] || p.delta[std::size_t(j)]) continue;
        auto lv = light_side(j + 1);
        auto cv = camera_side(k - j);
        float sum = technique_sum(lv.data(), j + 1, cv.data(), k - j, p.light_delta, m);
        std::vector<float> lt(lv.size()), ct(cv.size());
        subpath_tails(lv.data(), j + 1, false, p.light_delta, m, lt.data());
        subpath_tails(cv.data(), k - j, true, false, m, ct.data());
        EXPECT_NEAR(technique_sum(lv.data(), j + 1, cv.data(), k - j, p.light_delta, m, lt.data(), ct.data()),
                    sum, 1e-5f * sum);
        float p_cam = p.rev[std::size_t(j)] != 0 ? p.rev[std::size_t(j)] : 1.0f;
        float term = std::pow(p_cam * m.eta_vcm, m.power);
        ++*techniques;
        total += term / sum;
    }
    return total;
}

TEST(VcmMis, WeightsOfEveryTechniqueSumToOne) {
    PCG32 rng(17);
    int checked = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        SyntheticPath p;
        p.k = 1 + int(rng.uniform_float() * 7);
        const std::size_t n = std::size_t(p.k) + 1;
        p.fwd.assign(n, 0);
        p.rev.assign(n, 0);
        p.delta.assign(n, false);
        p.nonspecular.assign(n, false);
        for (std::size_t i = 0; i < n; ++i) {
            p.fwd[i] = std::exp(6 * rng.uniform_float() - 3);
            p.rev[i] = std::exp(6 * rng.uniform_float() - 3);
            p.nonspecular[i] = rng.uniform_float() < 0.8f;
        }
        // Interior specular vertices: both densities through them are deltas (0, as the walks store them).
        for (int i = 1; i < p.k; ++i)
            if (rng.uniform_float() < 0.25f) {
                p.delta[std::size_t(i)] = true;
                p.nonspecular[std::size_t(i)] = rng.uniform_float() < 0.3f; // a mixed BSDF
                p.fwd[std::size_t(i + 1)] = 0;
                p.rev[std::size_t(i - 1)] = 0;
            }
        p.light_delta = rng.uniform_float() < 0.2f;
        for (int mode = 0; mode < 3; ++mode) {
            MisTechniques m;
            m.vc = mode != 2;
            m.vm = mode != 1;
            m.eta_vcm = std::exp(4 * rng.uniform_float() - 2);
            m.n_lt = rng.uniform_float() < 0.5f ? 1.0f : 0.3f;
            m.power = rng.uniform_float() < 0.5f ? 1.0f : 2.0f;
            int techniques = 0;
            double total = weight_total(p, m, &techniques);
            if (techniques == 0) continue;
            ++checked;
            ASSERT_NEAR(total, 1.0, 1e-4) << "trial " << trial << " mode " << mode << " k " << p.k;
        }
    }
    EXPECT_GT(checked, 30000);
}

// The grid finds every point within r of a query exactly once, and no other (against brute force; points
// clustered on two planes and scattered, queries near and off them).
TEST(LightVertexGrid, FindsExactlyThePointsWithinTheRadius) {
    PCG32 rng(5);
    std::vector<Point3f> pts;
    for (int i = 0; i < 3000; ++i) {
        float u = rng.uniform_float(), v = rng.uniform_float();
        if (i % 3 == 0)
            pts.push_back(Point3f{u, v, 0.0f});
        else if (i % 3 == 1)
            pts.push_back(Point3f{u, 0.5f, v});
        else
            pts.push_back(Point3f{u * 2 - 1, v * 3, rng.uniform_float()});
    }
    // Renumbered by cell (number_by_cell), the visits go through `order` to the same points, and a cell's
    // points are visited in rising number (the data stored in that order is read forwards).
    for (bool by_cell : {false, true}) {
        for (float r : {0.003f, 0.05f, 0.4f}) {
            LightVertexGrid grid;
            grid.build(pts, r);
            std::vector<std::uint32_t> order(pts.size());
            for (std::size_t i = 0; i < pts.size(); ++i) order[i] = std::uint32_t(i);
            if (by_cell) {
                grid.number_by_cell(&order);
                std::vector<std::uint32_t> sorted = order;
                std::sort(sorted.begin(), sorted.end());
                for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(sorted[i], i) << "not a permutation";
            }
            for (int q = 0; q < 300; ++q) {
                Point3f x{rng.uniform_float() * 2.4f - 1.2f, rng.uniform_float() * 3.2f - 0.1f,
                          q % 2 ? 0.0f : rng.uniform_float() * 1.2f - 0.1f};
                if (q % 5 == 0) x = pts[std::size_t(q) * 7];
                std::vector<int> seen(pts.size(), 0);
                std::vector<std::uint32_t> numbers;
                grid.for_within(x, [&](std::uint32_t k) {
                    ++seen[order[k]];
                    numbers.push_back(k);
                });
                // Rising within each of the (at most 8) cells visited: at most 8 rising runs.
                int runs = numbers.empty() ? 0 : 1;
                for (std::size_t k = 1; k < numbers.size(); ++k) runs += numbers[k] < numbers[k - 1];
                if (by_cell) {
                    ASSERT_LE(runs, 8) << "r " << r << " query " << q;
                }
                for (std::size_t i = 0; i < pts.size(); ++i) {
                    bool within = length_squared(pts[i] - x) <= r * r;
                    ASSERT_EQ(seen[i], within ? 1 : 0) << "r " << r << " query " << q << " point " << i;
                }
            }
        }
    }
    LightVertexGrid empty;
    empty.build({}, 0.1f);
    int visits = 0;
    empty.for_within(Point3f{0, 0, 0}, [&](std::uint32_t) { ++visits; });
    EXPECT_EQ(visits, 0);
}

RenderSetup vcm(int spp, int max_depth = -2, std::uint64_t seed = 7) {
    return test::independent_setup("vcm", spp, false, max_depth, seed);
}

// The scene text with its Integrator directive replaced by vcm's with `params`.
std::string with_vcm(std::string scene, const std::string& params) {
    std::size_t a = scene.find("Integrator");
    std::size_t b = scene.find('\n', a);
    return scene.replace(a, b - a, "Integrator \"vcm\" " + params);
}

// Closed furnace (box filter, maxdepth D): every pixel sees Le Σ_{k<=D} ρ^k in every mode. Merging is
// exact here too: the radiance field is uniform, and a ball around a point of a sphere cuts π r² of it.
TEST(VCM, ClosedFurnace) {
    const double rho = 0.7, le = 0.5;
    const int depth = 8;
    const double e = le * (1 - std::pow(rho, depth + 1)) / (1 - rho);
    for (const char* mode : {"vcm", "vc", "vm"}) {
        std::string scene = test::closed_furnace(rho, le, 16);
        scene.insert(scene.find("WorldBegin"), "PixelFilter \"box\"\n");
        scene = with_vcm(scene, fmt::format("\"string mode\" \"{}\" \"float radius\" 0.05", mode));
        RenderResult r = render_pbrt(scene, vcm(16, depth));
        EXPECT_EQ(r.nonfinite_samples, 0u);
        for (int c = 0; c < 3; ++c) {
            auto m = pixel_mean(r.image, c);
            std::printf("furnace %-4s ch %d expected %.6g measured %.6g +- %.2g\n", mode, c, e, m.mean,
                        m.standard_error);
            EXPECT_NEAR(m.mean, e, kSigmas * m.standard_error + 2e-4 * e) << mode << " channel " << c;
        }
    }
}

// The mean over the pixels of a - b per channel within kSigmas of its standard error.
void expect_agree(const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.pixel_count(), b.pixel_count());
    const std::size_t n = a.pixel_count();
    for (int c = 0; c < 3; ++c) {
        double sum = 0, sum2 = 0, mean_a = 0;
        for (std::size_t i = 0; i < n; ++i) {
            double d = double(a.data()[i][c]) - b.data()[i][c];
            sum += d;
            sum2 += d * d;
            mean_a += a.data()[i][c];
        }
        double mean = sum / n, var = std::max(0.0, (sum2 - n * mean * mean) / (n - 1));
        double se = std::sqrt(var / n);
        std::printf("%-32s ch %d mean %.6g difference %.3g +- %.2g\n", what.c_str(), c, mean_a / n, mean, se);
        EXPECT_NEAR(mean, 0.0, kSigmas * se + 1e-4 * mean_a / n) << what << " channel " << c;
    }
}

// A small area light over a diffuse floor with a diffuse box and a glass sphere (caustics on the floor, the
// light seen directly and through the glass); bdpt_test.cpp's scene.
const char* kSurfaceScene = R"(
LookAt 0 -4 2.5  0 0 0.5  0 0 1
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [32] "integer yresolution" [32]
Sampler "independent"
Integrator "path" "integer maxdepth" [5]
WorldBegin
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [8 6 4]
  Translate 0.3 0.2 2.5
  ReverseOrientation
  Shape "disk" "float radius" [0.4]
AttributeEnd
Material "diffuse" "rgb reflectance" [0.6 0.6 0.6]
Shape "trianglemesh" "point3 P" [-5 -5 0 5 -5 0 5 5 0 -5 5 0] "integer indices" [0 1 2 0 2 3]
Material "diffuse" "rgb reflectance" [0.2 0.5 0.8]
Shape "trianglemesh" "point3 P" [-1.2 0.2 0  -0.6 0.2 0  -0.6 0.8 0  -1.2 0.8 0  -1.2 0.2 0.8  -0.6 0.2 0.8  -0.6 0.8 0.8  -1.2 0.8 0.8]
  "integer indices" [0 1 5 0 5 4  1 2 6 1 6 5  2 3 7 2 7 6  3 0 4 3 4 7  4 5 6 4 6 7]
Material "dielectric" "float eta" [1.5]
AttributeBegin
  Translate 0.4 -0.2 0.5
  Shape "sphere" "float radius" [0.5]
AttributeEnd
)";

// Each mode and the path tracer estimate the same image: the per-pixel differences average to zero
// (merging's blur over 0.01, a tenth of a pixel's footprint on the floor, is far below the noise).
TEST(VCM, ModesAgreeWithEachOtherAndThePathTracer) {
    RenderSetup p;
    p.integrator = "path";
    p.spp = 256;
    p.sampler = "independent";
    p.seed = 3;
    Image path = render_pbrt(kSurfaceScene, p).image;
    Image full =
        render_pbrt(with_vcm(kSurfaceScene, "\"float radius\" 0.01 \"integer maxdepth\" 5"), vcm(64)).image;
    for (const char* mode : {"vc", "vm"}) {
        RenderResult r =
            render_pbrt(with_vcm(kSurfaceScene,
                                 fmt::format("\"float radius\" 0.01 \"integer maxdepth\" 5 \"string mode\" "
                                             "\"{}\"",
                                             mode)),
                        vcm(64, -2, 11));
        EXPECT_EQ(r.nonfinite_samples, 0u);
        expect_agree(r.image, full, fmt::format("surfaces: {} - vcm", mode));
    }
    expect_agree(full, path, "surfaces: vcm - path");
    RenderResult power = render_pbrt(
        with_vcm(kSurfaceScene,
                 "\"float radius\" 0.01 \"integer maxdepth\" 5 \"string misheuristic\" \"power\""),
        vcm(64, -2, 13));
    expect_agree(power.image, path, "surfaces: vcm (power) - path");
}

// A box of chromatic scattering medium on a floor under a small area light (bdpt_test.cpp's scene): the
// connections carry the transport through the medium; merges happen on the floor only, and the weights
// count the medium vertices as vertices where no merge can happen. Agrees with volpath per pixel on average.
const std::string kMediumScene = test::box_on_floor_scene(test::kMediumBox);

TEST(VCM, AgreesWithVolPathInMedium) {
    RenderSetup p;
    p.integrator = "volpath";
    p.spp = 128;
    p.sampler = "independent";
    p.seed = 3;
    Image ref = render_pbrt(kMediumScene, p).image;
    RenderResult r =
        render_pbrt(with_vcm(kMediumScene, "\"integer maxdepth\" 6 \"float radius\" 0.02"), vcm(32));
    EXPECT_EQ(r.nonfinite_samples, 0u);
    expect_agree(r.image, ref, "medium: vcm - volpath");
}

TEST(VCM, SameImageAtAnyThreadCount) {
    // 48² with 1024-pixel chunks: three chunks of light subpaths and of pixels.
    std::string scene = with_vcm(kSurfaceScene, "\"float radius\" 0.05");
    scene.replace(scene.find("[32] \"integer yresolution\" [32]"), 31, "[48] \"integer yresolution\" [48]");
    for (bool spectral : {false, true}) {
        RenderSetup a = vcm(4);
        a.spectral = spectral;
        a.threads = 1;
        RenderSetup b = a;
        b.threads = 2;
        Image one = render_pbrt(scene, a).image, two = render_pbrt(scene, b).image;
        ASSERT_EQ(one.pixel_count(), two.pixel_count());
        for (std::size_t i = 0; i < one.pixel_count(); ++i)
            for (int c = 0; c < 3; ++c) ASSERT_EQ(one.data()[i][c], two.data()[i][c]) << "pixel " << i;
    }
}

TEST(VCM, ParametersAreChecked) {
    auto build = [](const std::string& params) {
        SceneDesc desc = parse_pbrt_string(with_vcm(kSurfaceScene, params), "<test>", ".");
        auto scene = build_scene(desc);
        return make_integrator(scene->request.integrator, *scene, scene->request.max_depth);
    };
    EXPECT_THROW(build("\"string mode\" \"photons\""), Error);
    EXPECT_THROW(build("\"float radius\" -1"), Error);
    EXPECT_THROW(build("\"integer photonsperiteration\" 0"), Error);
    EXPECT_THROW(build("\"string misheuristic\" \"maximum\""), Error);
    auto ok = build("\"integer photonsperiteration\" 500 \"float radius\" 0.02 \"integer maxdepth\" 7");
    auto* v = dynamic_cast<VCMIntegrator*>(ok.get());
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->light_subpaths_per_iteration(), 500);
    EXPECT_FLOAT_EQ(v->initial_radius(), 0.02f);
    EXPECT_EQ(v->settings().max_depth, 7);
    // Fewer light subpaths than pixels: light tracing's share is rescaled, the estimate unchanged.
    RenderResult r =
        render_pbrt(with_vcm(kSurfaceScene, "\"integer photonsperiteration\" 300 \"float radius\" "
                                            "0.01"),
                    vcm(64, -2, 21));
    RenderSetup p;
    p.integrator = "path";
    p.spp = 256;
    p.sampler = "independent";
    p.seed = 23;
    expect_agree(r.image, render_pbrt(kSurfaceScene, p).image, "surfaces: vcm (300 subpaths) - path");
}

class CornellVcm : public testing::Test {
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

Image render_cornell(int spp, std::uint64_t seed, bool spectral, int resolution) {
    return test::render_shared_scene("cornell-box", spp, seed, resolution, spectral, "vcm");
}

// At 64² (the reference is 1024²: only the means are compared).
TEST_F(CornellVcm, MatchesRgbReference) {
    Image ref = read_image(test::shared_dir() + "/refs/rgb/cornell-box.exr");
    expect_means(render_cornell(16, 1, false, 64), render_cornell(16, 2, false, 64), ref, "vcm rgb");
}

// Spectral: all subpaths of an iteration share its wavelengths, so the colour noise of the wavelength choice
// is common to every pixel (the pixels' spread does not show it): 64 iterations each at 48².
TEST_F(CornellVcm, MatchesSpectralReference) {
    Image ref = read_image(test::shared_dir() + "/refs/spectral/cornell-box.exr");
    expect_means(render_cornell(64, 1, true, 48), render_cornell(64, 2, true, 48), ref, "vcm spectral");
}

// Per pixel against the path tracer at 40²: d = (A - P)² - (A - B)²/2 - (P - Q)²/2 averages to zero when the
// two differ by noise only (A, B vcm; P, Q path; independent seeds; lightpath_test.cpp's check). Merging's
// blur (about a pixel) would show here where merging carries weight.
TEST_F(CornellVcm, PerPixelConsistentWithPathTracer) {
    const int res = 40;
    Image a = render_cornell(32, 1, false, res), b = render_cornell(32, 2, false, res);
    Image p = test::render_shared_scene("cornell-box", 64, 3, res, false, "path"),
          q = test::render_shared_scene("cornell-box", 64, 4, res, false, "path");
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
        std::printf("channel %d: MSE(vcm, path) / expected noise = %.3f; d = %.3g +- %.2g\n", c, mse / noise,
                    mean, se);
        EXPECT_LT(std::abs(mean), kSigmas * se) << "channel " << c;
    }
}

} // namespace
} // namespace illum
