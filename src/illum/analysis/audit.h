// BSDF audits (DESIGN.md §4.2): positivity, reciprocity, energy conservation, consistency of sample()
// with f() and pdf(), and a chi-square goodness-of-fit test of sample() against pdf(); delta (specular)
// models get their own direction and energy checks. All at fixed seeds, in double precision.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "illum/bsdf/bxdf.h"

namespace illum {

struct ModelSpec;
struct AuditCase;

enum class CheckStatus { Pass, Fail, Skip, Info };
const char* to_string(CheckStatus s);

struct CheckResult {
    std::string name;
    CheckStatus status = CheckStatus::Pass;
    std::string detail;
    // The figure the check judged, where it has one (NaN otherwise): energy, the largest albedo over the
    // directions and channels and its standard error; reciprocity, the worst relative difference.
    double value = std::numeric_limits<double>::quiet_NaN();
    double standard_error = std::numeric_limits<double>::quiet_NaN();
};

// What the audit needs to know about the model besides its BxDF.
struct AuditTraits {
    bool delta = false;         // only delta lobes
    bool lossless = false;      // albedo 1 at every angle
    bool non_physical = false;  // reciprocity/energy reported as Info
    bool stochastic = false;    // f() stochastic, pdf() approximate: no chi-square, no exact consistency
    float eta = 1;              // interior index, for generalised reciprocity of transmission
    std::string not_reciprocal; // non-empty: reciprocity does not hold, for this reason (check skipped)
};

struct AuditOptions {
    std::vector<double> theta_o_deg = {10, 50,
                                       80}; // outgoing directions (plus one from below if transmissive)
    double phi_o_deg = 35;
    int chi2_samples = 100000;
    int chi2_theta_bins = 36, chi2_phi_bins = 72;
    int energy_samples = 40000;
    // The weighted-histogram test of stochastic models (sample() against f()).
    int weighted_samples = 200000, weighted_cos_bins = 4, weighted_phi_bins = 8, weighted_f_per_bin = 4096;
    int quadrature_theta = 192;
    int pairs = 1000; // random direction pairs for positivity and reciprocity
    std::uint64_t seed = 12345;
    double significance = 0.01; // family-wise, Sidak-corrected over chi2_tests
    int chi2_tests = 1;         // number of chi-square tests in the family
};

struct AuditResult {
    std::string model, params;
    std::vector<CheckResult> checks;
    bool passed() const;
    int chi2_tests = 0;
};

struct ChiSquareResult {
    double statistic = 0, p_value = 1;
    int dof = 0;
    bool zero_pdf_hit = false; // a sample landed where the integrated pdf is 0
    std::string detail;
};

// Chi-square test of sample() against pdf() for one wo: a (θ, φ) histogram over the whole sphere with
// expected counts from Simpson integration of pdf() over each bin, bins of expected count < 5 pooled,
// failed and delta samples counted in one extra bin against 1 - ∫ pdf.
ChiSquareResult chi_square_test(const BxDF& bxdf, Vector3f wo, TransportMode mode, int samples,
                                int theta_bins, int phi_bins, std::uint64_t seed);

// Audits one BxDF.
AuditResult audit_bxdf(const BxDF& bxdf, const AuditTraits& traits, const AuditOptions& options);
// The number of chi-square tests audit_bxdf runs for these traits (for the Sidak correction).
int count_chi2_tests(const BxDF& bxdf, const AuditTraits& traits, const AuditOptions& options);

// Audits every case of a registered model's parameter grid (Sidak over the grid's chi-square tests when
// options.chi2_tests <= 1; pass a larger number to correct over a bigger family).
std::vector<AuditResult> audit_model(const ModelSpec& model, AuditOptions options);
// One case of a model's grid with the options as given (options.chi2_tests is the family's size).
AuditResult audit_case(const ModelSpec& model, const AuditCase& c, const AuditOptions& options);

} // namespace illum
