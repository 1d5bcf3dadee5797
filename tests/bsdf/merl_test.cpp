// MERL round trip: tabulate an analytic GGX conductor in the MERL format, write it, read it back, and
// compare; broken files give clear errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/conductor.h"
#include "illum/bsdf/merl.h"
#include "illum/bsdf/rough_conductor.h"
#include "illum/math/warp.h"
#include "illum/util/error.h"

namespace illum {
namespace {

std::string temp_path(const char* name) { return ::testing::TempDir() + name; }

TEST(Merl, RoundTripOfAnAnalyticGGX) {
    RoughConductorBxDF ggx(MicrofacetDistribution(MicrofacetType::GGX, 0.3f, 0.3f),
                           Fresnel{SampledSpectrum(kGoldEta), SampledSpectrum(kGoldK)});
    MerlTable table = MerlTable::from_bxdf(ggx);
    std::string path = temp_path("ggx.binary");
    table.write(path);
    MerlBxDF merl = MerlBxDF::load(path);
    // The fitted lobe recovers the roughness.
    EXPECT_NEAR(merl.fitted_alpha(), 0.3f, 0.05f);
    // Nearest-bin lookup against the analytic model at random directions: the tabulation error is small
    // on average (bins are ~1° wide).
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<float> U(0, 0.999f);
    double err = 0, ref = 0;
    for (int i = 0; i < 20000; ++i) {
        Vector3f wo = sample_uniform_hemisphere({U(rng), U(rng)}),
                 wi = sample_uniform_hemisphere({U(rng), U(rng)});
        if (wo.z < 0.05f || wi.z < 0.05f) continue;
        Color3 a = ggx.f(wo, wi, TransportMode::Radiance).rgb(),
               b = merl.f(wo, wi, TransportMode::Radiance).rgb();
        err += std::abs(a.g - b.g) * wi.z;
        ref += a.g * wi.z;
    }
    EXPECT_LT(err / ref, 0.05);
    // Albedo agrees.
    for (double t : {0.0, 45.0}) {
        Rgb64 qa = albedo_quadrature(ggx, direction_deg(t, 0), 128, true);
        Rgb64 qb = albedo_quadrature(merl, direction_deg(t, 0), 128, true);
        EXPECT_NEAR(qa[0], qb[0], 0.02) << t;
    }
    std::remove(path.c_str());
}

TEST(Merl, TruncatedOrWrongFilesGiveClearErrors) {
    std::string path = temp_path("bad.binary");
    auto expect = [&](const std::string& needle) {
        try {
            MerlTable::read(path);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    {
        std::ofstream out(path, std::ios::binary);
        std::int32_t dims[3] = {90, 90, 180};
        out.write(reinterpret_cast<const char*>(dims), sizeof dims);
        double v = 1;
        for (int i = 0; i < 1000; ++i) out.write(reinterpret_cast<const char*>(&v), sizeof v);
    }
    expect("truncated");
    {
        std::ofstream out(path, std::ios::binary);
        std::int32_t dims[3] = {90, 90, 360};
        out.write(reinterpret_cast<const char*>(dims), sizeof dims);
    }
    expect("wrong dimensions 90x90x360");
    {
        std::ofstream out(path, std::ios::binary);
        out.write("ab", 2);
    }
    expect("header");
    std::remove(path.c_str());
    expect("cannot open");
}

} // namespace
} // namespace illum
