// One check of `illum verify`: a quantity the renderer's own code measures against its closed form,
// with the estimator's standard error and the tolerance the verdict used. The rule for a Monte Carlo
// estimate is
//   |measured - expected| <= k σ + ε |expected|,
// k = 4 standard errors (a false alarm once in 16 000 checks for a normal estimate) and ε a stated
// allowance for float rounding or a known, bounded bias; a deterministic computation has σ = 0 and only ε.
// An estimate too noisy to decide fails too: σ above 1% of the expected value (a diverging estimator, a
// path throughput that grows without bound, has a huge σ that 4σ would cover), and so does a render that
// dropped non-finite samples. Seeds are fixed, so a run gives the same figures every time.
#pragma once

#include <cstdint>
#include <string>

namespace illum {

struct VerifyCheck {
    std::string group;       // radiometry, bsdf, lights, envmap
    std::string name;        // what is checked, with its configuration
    std::string closed_form; // the formula it is checked against
    double expected = 0, measured = 0, standard_error = 0, tolerance = 0;
    // An inequality, measured <= expected (+ tolerance), instead of an equality.
    bool upper_bound = false;
    bool passed = false;
    std::string detail;
};

struct VerifyOptions {
    int threads = 0; // renders: 0 for all hardware threads
    std::uint64_t seed = 1;
    double sigmas = 4;
    double max_relative_standard_error = 0.01;
};

struct Estimate {
    double mean = 0, standard_error = 0;
    std::uint64_t dropped = 0; // non-finite samples the render dropped
};

// The check with the tolerance k σ + ε |expected| (k = options.sigmas); a non-finite figure fails.
VerifyCheck judge(std::string group, std::string name, std::string closed_form, double expected,
                  Estimate measured, double relative_allowance, const VerifyOptions& options,
                  std::string detail = {});
// The same for three channels: every channel must pass; the one furthest from its expectation (in
// tolerances) is reported, its letter appended to the closed form.
VerifyCheck judge_rgb(std::string group, std::string name, std::string closed_form, const double expected[3],
                      const Estimate measured[3], double relative_allowance, const VerifyOptions& options,
                      std::string detail = {});

} // namespace illum
