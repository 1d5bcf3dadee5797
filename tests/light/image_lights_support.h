// Helpers for the tests of lights that read images: images written to temporary files, photon power
// estimates and render means.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include <fmt/format.h>

#include "illum/image/image_io.h"
#include "illum/light/light.h"
#include "illum/math/rng.h"
#include "math/stat_util.h"

namespace illum::test {

// `img` written as an EXR under the temporary folder (a name unique to this process and `tag`).
inline std::string temp_image(const Image& img, const std::string& tag) {
    std::string path =
        (std::filesystem::temp_directory_path() / fmt::format("illum_lights_{}_{}.exr", getpid(), tag))
            .string();
    write_image(img, path);
    return path;
}

// Photon flux of n photons of sample_le, per channel.
struct Photons {
    MeanAccumulator acc[3];
};
inline Photons photon_power(const Light& light, int n, std::uint64_t seed) {
    PCG32 rng(seed);
    Photons e;
    for (int i = 0; i < n; ++i) {
        Point2f u1{rng.uniform_float(), rng.uniform_float()}, u2{rng.uniform_float(), rng.uniform_float()};
        auto s = light.sample_le(u1, u2, SampledWavelengths::rgb_mode());
        for (int c = 0; c < 3; ++c) e.acc[c].add(s ? double(s->flux[c]) : 0.0);
    }
    return e;
}

// The photons' mean flux equals power() within 4 standard errors (plus `rel` of it).
inline void expect_photons_match_power(const Light& light, int n, std::uint64_t seed, const std::string& what,
                                       double rel = 1e-4) {
    Photons e = photon_power(light, n, seed);
    Color3 p = light.power().rgb();
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e.acc[c].mean, p[c], 4 * e.acc[c].std_error() + rel * std::abs(p[c]))
            << what << " channel " << c;
}

// For random photons, pdf_le of the photon's ray equals the densities sample_le returned.
// At least min_checked photons must have been emitted (a portal light's miss the portal most of the time).
inline void expect_pdf_le_matches(const Light& light, int n, std::uint64_t seed, const std::string& what,
                                  int min_checked = -1) {
    PCG32 rng(seed);
    int checked = 0;
    for (int i = 0; i < n; ++i) {
        Point2f u1{rng.uniform_float(), rng.uniform_float()}, u2{rng.uniform_float(), rng.uniform_float()};
        auto s = light.sample_le(u1, u2, SampledWavelengths::rgb_mode());
        if (!s) continue;
        AreaPdf pos(-1);
        SolidAnglePdf dir(-1);
        light.pdf_le(s->ray, s->n, &pos, &dir);
        EXPECT_NEAR(pos.value, s->pdf_pos.value, 1e-4f * s->pdf_pos.value) << what;
        EXPECT_NEAR(dir.value, s->pdf_dir.value, 2e-3f * s->pdf_dir.value) << what;
        ++checked;
    }
    EXPECT_GE(checked, min_checked < 0 ? n / 10 : min_checked) << what;
}

} // namespace illum::test
