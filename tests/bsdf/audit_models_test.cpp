// The audit of every registered model over its parameter grid (DESIGN.md §4.2): positivity, reciprocity,
// energy, sample()/f()/pdf() consistency and the chi-square test at fixed seeds, 1% family-wise
// significance with the Sidak correction over each model's grid.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

#include "illum/analysis/audit.h"
#include "illum/bsdf/registry.h"
#include "illum/math/rng.h"
#include "illum/math/warp.h"

namespace illum {
namespace {

class AuditModel : public ::testing::TestWithParam<std::string> {};

TEST_P(AuditModel, PassesEveryCheckOverItsGrid) {
    const ModelSpec& model = find_bxdf_model(GetParam());
    ASSERT_FALSE(model.audit_grid.empty());
    AuditOptions options;
    options.chi2_samples = 60000;
    options.energy_samples = 20000;
    options.quadrature_theta = 128;
    options.pairs = 500;
    for (const auto& r : audit_model(model, options)) {
        for (const auto& c : r.checks)
            EXPECT_NE(c.status, CheckStatus::Fail)
                << r.model << " " << r.params << ": " << c.name << ": " << c.detail;
        // Every check that can run does run: physical non-delta models run the chi-square test.
        if (!model.delta && !model.stochastic) {
            EXPECT_GT(r.chi2_tests, 0) << r.model;
        }
    }
}

// A model that says its sample() does not read uc (reads_lobe_sample() false, so the integrators leave that
// sampler dimension uncomputed) must sample the same direction, value and density for any uc.
TEST_P(AuditModel, IgnoresTheLobeSampleWhereItSaysSo) {
    const ModelSpec& model = find_bxdf_model(GetParam());
    for (const AuditCase& c : model.audit_grid) {
        std::unique_ptr<BxDF> bxdf = model.make(resolve_params(model, c.params));
        if (bxdf->reads_lobe_sample()) continue;
        PCG32 rng(7);
        for (int i = 0; i < 500; ++i) {
            const Point2f uw{rng.uniform_float(), rng.uniform_float()},
                u{rng.uniform_float(), rng.uniform_float()};
            Vector3f wo = sample_uniform_sphere(uw);
            if (wo.z == 0) continue;
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                auto a = bxdf->sample(wo, 0.01f, u, mode), b = bxdf->sample(wo, 0.99f, u, mode);
                ASSERT_EQ(bool(a), bool(b)) << model.name;
                if (!a) continue;
                EXPECT_EQ(a->wi, b->wi) << model.name;
                EXPECT_EQ(a->pdf.value, b->pdf.value) << model.name;
                for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_EQ(a->f.s[k], b->f.s[k]) << model.name;
            }
        }
    }
}

// The largest relative change of f() and pdf() over random pairs of directions when both turn together
// about the normal by a random angle (a direction's rounding under the turn changes them by ~1e-6).
float rotation_deviation(const BxDF& bxdf) {
    PCG32 rng(11);
    float worst = 0;
    auto relative = [](float a, float b) {
        return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-6f});
    };
    for (int i = 0; i < 500; ++i) {
        Vector3f wo = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()}),
                 wi = sample_uniform_sphere({rng.uniform_float(), rng.uniform_float()});
        if (wo.z == 0 || wi.z == 0) continue;
        const float phi = 2 * kPi * rng.uniform_float(), c = std::cos(phi), s = std::sin(phi);
        auto turn = [&](Vector3f w) { return Vector3f{c * w.x - s * w.y, s * w.x + c * w.y, w.z}; };
        for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
            Bsdf3 a = bxdf.f(wo, wi, mode), b = bxdf.f(turn(wo), turn(wi), mode);
            for (int k = 0; k < kSpectrumSamples; ++k) worst = std::max(worst, relative(a.s[k], b.s[k]));
            worst = std::max(
                worst, relative(bxdf.pdf(wo, wi, mode).value, bxdf.pdf(turn(wo), turn(wi), mode).value));
            // A model of delta lobes only has no f() to compare: its sampled direction turns with wo.
            if (has_flag(bxdf.flags(), kDiffuse) || has_flag(bxdf.flags(), kGlossy)) continue;
            const float uc = rng.uniform_float();
            auto sa = bxdf.sample(wo, uc, {0.5f, 0.5f}, mode),
                 sb = bxdf.sample(turn(wo), uc, {0.5f, 0.5f}, mode);
            if (bool(sa) != bool(sb)) return 1;
            if (!sa) continue;
            worst = std::max(worst, length(turn(sa->wi) - sb->wi));
            worst = std::max(worst, relative(sa->pdf.value, sb->pdf.value));
            for (int k = 0; k < kSpectrumSamples; ++k)
                worst = std::max(worst, relative(sa->f.s[k], sb->f.s[k]));
        }
    }
    return worst;
}

// A model that says it is isotropic (BxDF::isotropic, so the materials place it in a frame without the
// surface's tangent: placed() in bsdf/material.h) must be unchanged by a turn about the normal.
TEST_P(AuditModel, IsUnchangedByATurnAboutTheNormalWhereItSaysSo) {
    const ModelSpec& model = find_bxdf_model(GetParam());
    for (const AuditCase& c : model.audit_grid) {
        std::unique_ptr<BxDF> bxdf = model.make(resolve_params(model, c.params));
        if (bxdf->isotropic()) EXPECT_LT(rotation_deviation(*bxdf), 1e-3f) << model.name;
    }
}

// The check above can fail: an anisotropic rough conductor changes by far more under a turn.
TEST(AuditIsotropy, SeesAnAnisotropicModelChange) {
    const ModelSpec& model = find_bxdf_model("rough-conductor");
    std::unique_ptr<BxDF> aniso = model.make(
        resolve_params(model, std::map<std::string, std::string>{{"alpha_x", "0.1"}, {"alpha_y", "0.4"}}));
    EXPECT_FALSE(aniso->isotropic());
    EXPECT_GT(rotation_deviation(*aniso), 0.1f);
    std::unique_ptr<BxDF> iso =
        model.make(resolve_params(model, std::map<std::string, std::string>{{"alpha", "0.3"}}));
    EXPECT_TRUE(iso->isotropic());
}

std::vector<std::string> all_models() {
    std::vector<std::string> names;
    for (const auto& m : bxdf_models()) names.push_back(m.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Registry, AuditModel, ::testing::ValuesIn(all_models()), [](const auto& info) {
    std::string s = info.param;
    for (char& ch : s)
        if (ch == '-') ch = '_';
    return s;
});

TEST(Registry, NamesEveryModelOfTheIssue) {
    for (const char* name :
         {"lambert", "oren-nayar", "mirror", "dielectric", "thin-dielectric", "conductor", "phong",
          "blinn-phong", "torrance-sparrow", "cook-torrance", "rough-conductor", "rough-dielectric", "ward",
          "coated-diffuse", "coated-conductor", "diffuse-transmission", "merl", "toon"})
        EXPECT_NO_THROW(find_bxdf_model(name)) << name;
}

} // namespace
} // namespace illum
