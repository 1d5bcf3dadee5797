// Every integrator renders the same image (label "long"): on the Cornell box (RGB mode) its channel means are
// within 1% of the converged RGB reference and its pixels differ from the path tracer's at 1024 spp by noise
// only; on veach-bidir and veach-mis (spectral mode, exactly what pbrt-v4 renders) the same against pbrt-v4's
// references. Two renders A, B of independent seeds give the noise (test::pixel_check): a channel mean must
// be within 1% + 4.5 σ, and d = (A - ref)² - (A - B)²/2 must average to no more than the reference's own
// variance + 4.5 of its standard errors. SPPM is consistent rather than unbiased: its photons are gathered
// over a radius, so its pixels are a blur of the exact ones until the radius has shrunk; it is held to the
// means only, and its per-pixel figure is printed. VCM merges over a radius too, but only where merging
// has most of the MIS weight (caustics); with its default radius (about a pixel's footprint) it is held to
// both.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>

#include "illum/image/image_io.h"
#include "illum/render/renderer.h"
#include "illum/scene/build.h"
#include "illum/scene/pbrt/parser.h"
#include "test_support.h"

namespace illum {
namespace {

struct Case {
    const char* scene;
    const char* integrator;
    int spp;
    bool spectral;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scene << "/" << c.integrator; }

// The scene's test.pbrt with `integrator`; SPPM with photons per iteration = pixels and a radius of 1/250
// of the scene's bounding radius.
Image render_case(const std::string& scene_name, const std::string& integrator, int spp, std::uint64_t seed,
                  bool spectral) {
    return test::render_shared_scene(scene_name, spp, seed, 0, spectral, integrator, 0, [&](Scene& scene) {
        if (integrator != "sppm") return;
        Point3f c;
        float r = 0;
        scene.accelerator.bounds().bounding_sphere(&c, &r);
        scene.request.sppm_radius = r / 250;
        scene.request.sppm_photons_per_iteration = -1;
    });
}

// The path tracer at high sample counts (once): the mean of two renders, and its per-pixel variance per
// channel (the mean over pixels of (R1 - R2)²/4, the variance of the mean of two).
struct PathReference {
    Image image;
    double variance[3] = {0, 0, 0};
};

const PathReference& path_reference(const std::string& scene, int spp) {
    static std::map<std::string, std::unique_ptr<PathReference>> cache;
    auto& slot = cache[scene];
    if (!slot) {
        Image r1 = render_case(scene, "path", spp, 99, false),
              r2 = render_case(scene, "path", spp, 100, false);
        slot = std::make_unique<PathReference>();
        slot->image = Image(r1.width(), r1.height());
        for (std::size_t i = 0; i < r1.pixel_count(); ++i) {
            slot->image.data()[i] = (r1.data()[i] + r2.data()[i]) * 0.5f;
            for (int c = 0; c < 3; ++c) {
                double d = double(r1.data()[i][c]) - r2.data()[i][c];
                slot->variance[c] += d * d / 4 / double(r1.pixel_count());
            }
        }
    }
    return *slot;
}

constexpr int kPathReferenceSpp = 1024;

class Agreement : public testing::TestWithParam<Case> {
protected:
    void SetUp() override {
        if (!test::have_shared()) GTEST_SKIP() << "ILLUM_SHARED_DIR has no scenes";
    }
};

TEST_P(Agreement, MatchesTheReferences) {
    const Case& c = GetParam();
    Image a = render_case(c.scene, c.integrator, c.spp, 1, c.spectral);
    Image b = render_case(c.scene, c.integrator, c.spp, 2, c.spectral);
    const bool sppm = std::string(c.integrator) == "sppm";
    // Means: against the RGB reference (Cornell box, RGB mode) or pbrt-v4's (spectral mode).
    Image mean_ref =
        read_image(test::shared_dir() + (c.spectral ? "/refs/spectral/" : "/refs/rgb/") + c.scene + ".exr");
    // Pixels: against the path tracer (RGB) or pbrt-v4 (spectral), with the reference's own variance.
    const PathReference* path = c.spectral ? nullptr : &path_reference(c.scene, kPathReferenceSpp);
    const Image& pixel_ref = path ? path->image : mean_ref;
    Color3 ma = a.channel_mean(), mb = b.channel_mean(), mr = mean_ref.channel_mean();
    for (int ch = 0; ch < 3; ++ch) {
        test::PixelCheck k = test::pixel_check(a, b, pixel_ref, ch);
        double m = 0.5 * (ma[ch] + mb[ch]);
        double diff = m / mr[ch] - 1, sigma = k.mean_sigma / mr[ch];
        // pbrt-v4's variance at its 4096 spp, estimated from this render's as SharedSceneSpectral does (an
        // upper bound where this integrator is the noisier one); the path tracer's measured.
        double ref_var = path ? path->variance[ch] : k.mse_noise * c.spp / 4096;
        std::printf("%s %s%s ch %d: mean %+.2f%% (sigma %.2f%%), d = %.3g +- %.3g (reference variance %.3g), "
                    "MSE / noise %.3f\n",
                    c.scene, c.integrator, c.spectral ? " (spectral)" : "", ch, 100 * diff, 100 * sigma,
                    k.d_mean, k.d_se, ref_var, k.mse_ref / k.mse_noise);
        EXPECT_LT(std::abs(diff), 0.01 + 4.5 * sigma) << "channel " << ch;
        if (!sppm) {
            EXPECT_LT(k.d_mean, ref_var + 4.5 * k.d_se) << "channel " << ch;
        }
    }
}

const Case kCases[] = {
    {"cornell-box", "path", 64, false},
    {"cornell-box", "volpath", 64, false},
    {"cornell-box", "bdpt", 32, false},
    {"cornell-box", "lightpath", 64, false},
    {"cornell-box", "sppm", 64, false},
    {"veach-bidir", "path", 256, true},
    {"veach-bidir", "volpath", 256, true},
    {"veach-bidir", "bdpt", 64, true},
    {"veach-bidir", "lightpath", 256, true},
    {"veach-bidir", "sppm", 128, true},
    {"veach-mis", "path", 64, true},
    {"veach-mis", "volpath", 64, true},
    {"veach-mis", "bdpt", 32, true},
    {"veach-mis", "lightpath", 64, true},
    {"veach-mis", "sppm", 64, true},
    {"cornell-box", "vcm", 32, false},
    {"veach-bidir", "vcm", 64, true},
    // veach-mis's VCM at 1024 iterations, not 32. Its merges are biased while the radius is large: over eight
    // seeds at 32 iterations the channel means lay +1.98% above pbrt-v4's (standard error 0.58%), at 256
    // +0.9%. And each iteration's wavelengths are shared by the whole image, so a render's channel mean also
    // varies by 1.6% from seed to seed at 32 iterations, where the pixels' sigma (which this check uses)
    // sees 0.5%: at 32 iterations the check passed or failed with its two renders' wavelengths (+3.3%
    // against 1% + 4.5 sigma = 3.2%). At 1024 the bias and the wavelengths' share are a few tenths of a
    // percent (docs/verification.md).
    {"veach-mis", "vcm", 1024, true},
};

INSTANTIATE_TEST_SUITE_P(Integrators, Agreement, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& i) {
                             std::string n = std::string(i.param.scene) + "_" + i.param.integrator;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

} // namespace
} // namespace illum
