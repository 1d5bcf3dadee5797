#include "illum/analysis/bsdf_checks.h"

#include <cmath>

#include <fmt/format.h>
#include <oneapi/tbb/parallel_for.h>

#include "illum/bsdf/registry.h"

namespace illum {

namespace {

const char* kEnergyForm = "largest ρ(θo) = ∫ f |cos θi| dωi <= 1 (= 1 lossless)";
const char* kReciprocityForm = "f(wo, wi) = f(wi, wo) (the worst relative difference)";
const char* kSamplingForm = "positivity, sample() = f()/pdf(), chi-square at 1%: audits failed";

const CheckResult* find(const AuditResult& r, const std::string& name) {
    for (const CheckResult& c : r.checks)
        if (c.name == name) return &c;
    return nullptr;
}

// The verdict of several audit results' check `name`: failed if any failed; the figure of the worst case.
VerifyCheck summarise(const std::vector<AuditResult>& results, const std::string& model,
                      const std::string& check, const VerifyOptions& o) {
    VerifyCheck v;
    v.group = "bsdf";
    v.passed = true;
    bool energy = check == "energy";
    v.name = fmt::format("{} {}: {} parameter case{}", check, model, results.size(),
                         results.size() == 1 ? "" : "s");
    v.closed_form = energy ? kEnergyForm : kReciprocityForm;
    v.expected = energy ? 1.0 : 0.0;
    v.measured = 0;
    std::string info;
    for (const AuditResult& r : results) {
        const CheckResult* c = find(r, check);
        if (!c) continue;
        if (c->status == CheckStatus::Fail) {
            if (v.passed) v.detail = r.params + ": " + c->detail;
            v.passed = false;
        }
        if (c->status == CheckStatus::Info && info.empty()) info = c->detail;
        if (c->status == CheckStatus::Skip && v.detail.empty()) v.detail = "skipped: " + c->detail;
        if (std::isfinite(c->value) && std::abs(c->value) >= std::abs(v.measured)) {
            v.measured = c->value;
            v.standard_error = std::isfinite(c->standard_error) ? c->standard_error : 0.0;
        }
    }
    // The audits' own rules: albedo above 1 + 4σ + 10⁻³ (each case's σ); a deterministic model's relative
    // difference above 5·10⁻³; a stochastic one's mean difference beyond 4.5σ.
    bool stochastic = !energy && v.standard_error > 0;
    v.tolerance = energy ? o.sigmas * v.standard_error + 1e-3 : (stochastic ? 4.5 * v.standard_error : 5e-3);
    v.upper_bound = !stochastic;
    if (v.passed && !info.empty()) v.detail = info;
    return v;
}

VerifyCheck sampling(const std::vector<AuditResult>& results, const std::string& model) {
    VerifyCheck v;
    v.group = "bsdf";
    v.name = fmt::format("sampling {}: {} parameter case{}", model, results.size(),
                         results.size() == 1 ? "" : "s");
    v.closed_form = kSamplingForm;
    int failed = 0;
    for (const AuditResult& r : results)
        for (const CheckResult& c : r.checks) {
            if (c.name == "energy" || c.name == "reciprocity" || c.status != CheckStatus::Fail) continue;
            if (failed == 0) v.detail = r.params + ": " + c.name + ": " + c.detail;
            ++failed;
        }
    v.measured = failed;
    v.passed = failed == 0;
    return v;
}

} // namespace

std::vector<VerifyCheck> check_bsdf_audits(const VerifyOptions& o) {
    const auto& models = bxdf_models();
    AuditOptions ao;
    int tests = 0;
    for (const ModelSpec& m : models)
        for (const AuditCase& c : m.audit_grid) {
            AuditTraits t;
            t.delta = m.delta;
            t.stochastic = m.stochastic;
            tests += count_chi2_tests(*m.make(resolve_params(m, c.params)), t, ao);
        }
    ao.chi2_tests = std::max(1, tests);
    // Every case of every model, in parallel (the cases' costs differ by a hundredfold).
    std::vector<std::pair<std::size_t, std::size_t>> cases;
    for (std::size_t i = 0; i < models.size(); ++i)
        for (std::size_t k = 0; k < models[i].audit_grid.size(); ++k) cases.push_back({i, k});
    std::vector<AuditResult> done(cases.size());
    tbb::parallel_for(std::size_t(0), cases.size(), std::size_t(1), [&](std::size_t j) {
        const ModelSpec& m = models[cases[j].first];
        done[j] = audit_case(m, m.audit_grid[cases[j].second], ao);
    });
    std::vector<std::vector<AuditResult>> results(models.size());
    for (std::size_t j = 0; j < cases.size(); ++j) results[cases[j].first].push_back(std::move(done[j]));
    std::vector<VerifyCheck> out;
    for (std::size_t i = 0; i < models.size(); ++i) {
        out.push_back(summarise(results[i], models[i].name, "energy", o));
        out.push_back(summarise(results[i], models[i].name, "reciprocity", o));
        out.push_back(sampling(results[i], models[i].name));
    }
    return out;
}

VerifyCheck check_bxdf_energy(const BxDF& bxdf, const std::string& name, const AuditTraits& traits,
                              const VerifyOptions& o) {
    AuditResult r = audit_bxdf(bxdf, traits, AuditOptions{});
    r.params = name;
    return summarise({r}, name, "energy", o);
}

VerifyCheck check_bxdf_reciprocity(const BxDF& bxdf, const std::string& name, const AuditTraits& traits,
                                   const VerifyOptions& o) {
    AuditResult r = audit_bxdf(bxdf, traits, AuditOptions{});
    r.params = name;
    return summarise({r}, name, "reciprocity", o);
}

} // namespace illum
