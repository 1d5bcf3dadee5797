// The audit of every registered model over its parameter grid (DESIGN.md §4.2): positivity, reciprocity,
// energy, sample()/f()/pdf() consistency and the chi-square test at fixed seeds, 1% family-wise
// significance with the Sidak correction over each model's grid.
#include <gtest/gtest.h>

#include "illum/analysis/audit.h"
#include "illum/bsdf/registry.h"

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
