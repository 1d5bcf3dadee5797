// Long SPPM check (label "long"): the water caustic in spectral mode at pbrt-v4's 512 iterations (the
// scene's own 16384 photons per iteration; the reference has 200000) against refs/spectral/water-caustic.exr.
// The short test (tests/integrators/sppm_test.cpp) holds 64 iterations to 3% (measured there: within 0.6%,
// and 2.3% at 16 iterations); 8x the iterations here, so 1.5%, which leaves room for the radius bias: ours
// shrinks more slowly than the reference's, which gathers 12x the photons per iteration. Measured: +0.28%
// +0.17% +0.59% in 23 s on 2 cores.
#include <gtest/gtest.h>

#include <cstdio>

#include "../integrators/sppm_support.h"
#include "illum/image/image_io.h"

namespace illum {
namespace {

TEST(SppmLong, WaterCausticSpectral512Iterations) {
    if (!test::have_shared()) GTEST_SKIP() << "ILLUM_SHARED_DIR has no scenes";
    Image ref = read_image(test::shared_dir() + "/refs/spectral/water-caustic.exr");
    const std::string dir = test::shared_dir() + "/scenes/water-caustic";
    test::SppmSetup s;
    s.iterations = 512;
    s.spectral = true;
    test::SppmRun run = test::render_sppm(test::read_text(dir + "/test.pbrt"), dir, s);
    // The light's own pixels (reference above 20) are left out, as in the short test.
    double a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
    int masked = 0;
    for (int y = 0; y < ref.height(); ++y)
        for (int x = 0; x < ref.width(); ++x) {
            if (ref(x, y).max_component() > 20) {
                ++masked;
                continue;
            }
            for (int c = 0; c < 3; ++c) {
                a[c] += run.result.image(x, y)[c];
                b[c] += ref(x, y)[c];
            }
        }
    std::printf("512 iterations in %.1f s, %d pixels left out: %+.2f%% %+.2f%% %+.2f%%\n", run.result.seconds,
                masked, 100 * (a[0] / b[0] - 1), 100 * (a[1] / b[1] - 1), 100 * (a[2] / b[2] - 1));
    EXPECT_LE(masked, 8);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c] / b[c], 1, 0.015) << "channel " << c;
}

} // namespace
} // namespace illum
