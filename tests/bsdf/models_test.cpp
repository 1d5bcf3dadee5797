// Model-specific checks: Lambert's albedo, Fresnel identities, smooth dielectric weights, layered energy,
// and parameter validation.
#include <gtest/gtest.h>

#include <random>

#include "illum/bsdf/albedo.h"
#include "illum/bsdf/coated.h"
#include "illum/bsdf/conductor.h"
#include "illum/bsdf/dielectric.h"
#include "illum/bsdf/fresnel.h"
#include "illum/bsdf/lambert.h"
#include "illum/bsdf/registry.h"
#include "illum/bsdf/thin_dielectric.h"
#include "illum/geometry/surface_hit.h"
#include "illum/util/error.h"

namespace illum {
namespace {

TEST(Lambert, AlbedoIsRhoWithinMonteCarloError) {
    LambertBxDF lambert(SampledSpectrum(Color3(0.2f, 0.5f, 0.9f)));
    for (double t : {0.0, 30.0, 60.0, 80.0}) {
        Rgb64 mean, se;
        albedo_monte_carlo(lambert, direction_deg(t, 10), 20000, 7, &mean, &se);
        Rgb64 quad = albedo_quadrature(lambert, direction_deg(t, 10), 128, true);
        for (int c = 0; c < 3; ++c) {
            double rho = Color3(0.2f, 0.5f, 0.9f)[c];
            EXPECT_NEAR(mean[c], rho, 4 * se[c] + 1e-6) << t;
            EXPECT_NEAR(quad[c], rho, 1e-4) << t;
        }
    }
}

TEST(Fresnel, NormalIncidenceIsSquaredRatio) {
    for (float eta : {1.2f, 1.5f, 2.4f, 0.7f}) {
        EXPECT_NEAR(fresnel_dielectric(1, eta), sqr((eta - 1) / (eta + 1)), 1e-6f) << eta;
        EXPECT_NEAR(fresnel_dielectric_schlick(1, eta), sqr((eta - 1) / (eta + 1)), 1e-6f) << eta;
    }
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
    float eta = 1.5f, critical = std::asin(1 / eta);
    EXPECT_EQ(fresnel_dielectric(-std::cos(critical + 0.01f), eta), 1.0f);
    EXPECT_LT(fresnel_dielectric(-std::cos(critical - 0.01f), eta), 1.0f);
    EXPECT_EQ(fresnel_dielectric_schlick(-std::cos(critical + 0.01f), eta), 1.0f);
    // Seen from inside, the same pair of angles reflects the same (Stokes relations).
    float ci = 0.8f, si = std::sqrt(1 - ci * ci), ct = std::sqrt(1 - si * si / (eta * eta));
    EXPECT_NEAR(fresnel_dielectric(ci, eta), fresnel_dielectric(-ct, eta), 1e-5f);
}

TEST(Fresnel, ConductorWithZeroExtinctionIsDielectric) {
    for (float eta : {1.1f, 1.5f, 3.0f})
        for (float c = 0.01f; c <= 1; c += 0.07f)
            EXPECT_NEAR(fresnel_complex(c, std::complex<float>(eta, 0)), fresnel_dielectric(c, eta), 1e-5f);
    // Gold reflects strongly and more in red than blue.
    Color3 f0 = fresnel_complex(1, kGoldEta, kGoldK);
    EXPECT_GT(f0.r, 0.9f);
    EXPECT_GT(f0.r, f0.b);
    EXPECT_NEAR(f0.g, conductor_f0(SampledSpectrum(kGoldEta), SampledSpectrum(kGoldK))[1], 1e-5f);
    EXPECT_NEAR(fresnel_complex(0, kGoldEta, kGoldK).g, 1, 1e-5f); // grazing: 1
}

TEST(Fresnel, SchlickErrorIsBounded) {
    // Known bounds of Schlick's approximation: exact at 0° and 90°, within 0.04 in between for η = 1.5.
    double worst = 0;
    for (int i = 0; i <= 90; ++i) {
        float c = std::cos(i * kPi / 180);
        worst = std::max(worst,
                         double(std::abs(fresnel_dielectric(c, 1.5f) - fresnel_dielectric_schlick(c, 1.5f))));
    }
    EXPECT_LT(worst, 0.04); // the largest error, ~0.036, is near 80°
    EXPECT_GT(worst, 1e-3); // it is an approximation, not the same function
    EXPECT_NEAR(fresnel_schlick(0, 0.04f), 1, 1e-6f);
}

TEST(Dielectric, ReflectionFractionIsFresnelAndWeightsAreExact) {
    DielectricBxDF glass(1.5f);
    Vector3f wo = direction_deg(60, 20);
    float F = fresnel_dielectric(wo.z, 1.5f);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<float> U(0, 0.999999f);
    int n = 20000, reflected = 0;
    for (int i = 0; i < n; ++i) {
        auto s = glass.sample(wo, U(rng), {U(rng), U(rng)}, TransportMode::Radiance);
        ASSERT_TRUE(s);
        if (s->is_reflection()) {
            ++reflected;
            EXPECT_NEAR(s->weight()[0], 1, 1e-5f);
        } else {
            // Radiance mode scales refracted radiance by 1/η².
            EXPECT_NEAR(s->weight()[0], 1 / (1.5f * 1.5f), 1e-5f);
            EXPECT_NEAR(s->eta, 1.5f, 1e-6f);
            // Snell: sin θt = sin θi / η.
            EXPECT_NEAR(sin_theta(s->wi), sin_theta(wo) / 1.5f, 1e-5f);
        }
    }
    double p = double(reflected) / n, se = std::sqrt(F * (1 - F) / n);
    EXPECT_NEAR(p, F, 4 * se);
    // From inside beyond the critical angle everything reflects.
    auto s = glass.sample(direction_deg(180 - 60, 0), 0.99f, {0.5f, 0.5f}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->is_reflection());
}

TEST(ThinDielectric, ReflectsMoreThanOneFaceAndIsLossless) {
    ThinDielectricBxDF pane(1.5f);
    for (float c : {1.0f, 0.7f, 0.3f}) {
        float R1 = fresnel_dielectric(c, 1.5f);
        EXPECT_GT(pane.reflectance(c), R1);
        EXPECT_LE(pane.reflectance(c), 1);
    }
    EXPECT_NEAR(pane.reflectance(1), 2 * 0.04f / (1 + 0.04f), 1e-5f); // 2R/(1+R) at normal incidence
}

TEST(CoatedDiffuse, WhiteBaseLosesOnlyTruncatedWalks) {
    CoatedDiffuseBxDF coated(DielectricInterface(1.5f, {0, 0}), LambertBxDF(SampledSpectrum(1)),
                             LayerMedium{0, SampledSpectrum(0.0f), 0}, 100, 1);
    Rgb64 mean, se;
    albedo_monte_carlo(coated, direction_deg(30, 0), 20000, 5, &mean, &se);
    EXPECT_NEAR(mean[0], 1, 4 * se[0] + 0.01);
    CoatedDiffuseBxDF grey(DielectricInterface(1.5f, {0, 0}), LambertBxDF(SampledSpectrum(0.5f)),
                           LayerMedium{}, 100, 1);
    albedo_monte_carlo(grey, direction_deg(30, 0), 20000, 5, &mean, &se);
    EXPECT_LT(mean[0], 0.6);
    EXPECT_GT(mean[0], 0.3);
}

// Every name a model's constructor looks up is one of its spec's parameters, on the heap (every audit case)
// and in the arena at a shading point: a misspelt "kd"_p would silently read zero.
TEST(Registry, ConstructorsReadOnlyTheirSpecsParameters) {
    int before = ModelArgs::misses();
    ScratchArena arena;
    SurfaceHit hit;
    for (const ModelSpec& spec : bxdf_models())
        for (const AuditCase& c : spec.audit_grid) {
            ParamValues v = resolve_params(spec, c.params);
            EXPECT_NE(spec.make(v), nullptr) << spec.name;
            if (spec.factory.place) {
                EXPECT_NE(spec.factory.place(ModelArgs(v.args, &hit), arena), nullptr);
            }
        }
    EXPECT_EQ(ModelArgs::misses(), before);
    const std::vector<ModelArg> no_args;
    ModelArgs none(no_args, nullptr);
    EXPECT_EQ(none.scalar("nonexistent"_p), 0.0f); // what a miss reads, counted
    EXPECT_EQ(ModelArgs::misses(), before + 1);
}

TEST(Registry, RejectsBadInput) {
    auto expect_error = [](const std::string& model, std::map<std::string, std::string> p,
                           const std::string& needle) {
        try {
            make_bxdf(model, p);
            ADD_FAILURE() << "no error for " << model;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    expect_error("glass", {}, "unknown BRDF model 'glass'");
    expect_error("lambert", {{"roughness", "1"}}, "has no parameter 'roughness'");
    expect_error("rough-conductor", {{"alpha", "-0.1"}}, "must be in [0.001, 2]");
    expect_error("dielectric", {{"eta", "0"}}, "'eta'");
    expect_error("dielectric", {{"eta", "-1"}}, "'eta'");
    expect_error("dielectric", {{"eta", "abc"}}, "not a number");
    expect_error("lambert", {{"reflectance", "1,2"}}, "r,g,b");
    expect_error("phong", {{"kd", "0.8"}, {"ks", "0.8"}}, "kd + ks");
    expect_error("rough-conductor", {{"distribution", "phong"}}, "one of ggx, beckmann");
    expect_error("merl", {}, "'file' is required");
    expect_error("merl", {{"file", "/nonexistent/x.binary"}},
                 "cannot open MERL file '/nonexistent/x.binary': No such file or directory");
    // Constructors validate too.
    EXPECT_THROW(DielectricBxDF(-1.0f), Error);
    EXPECT_THROW(ConductorBxDF(SampledSpectrum(0), SampledSpectrum(1)), Error);
}

} // namespace
} // namespace illum
