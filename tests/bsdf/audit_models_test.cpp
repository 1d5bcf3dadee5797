// The audit of every registered model over its parameter grid (DESIGN.md §4.2): positivity, reciprocity,
// energy, sample()/f()/pdf() consistency and the chi-square test at fixed seeds, 1% family-wise
// significance with the Sidak correction over each model's grid.
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
