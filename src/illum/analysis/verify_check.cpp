#include "illum/analysis/verify_check.h"

#include <cmath>

#include <fmt/format.h>

namespace illum {

VerifyCheck judge(std::string group, std::string name, std::string closed_form, double expected, Estimate m,
                  double relative_allowance, const VerifyOptions& o, std::string detail) {
    VerifyCheck c;
    c.group = std::move(group);
    c.name = std::move(name);
    c.closed_form = std::move(closed_form);
    c.expected = expected;
    c.measured = m.mean;
    c.standard_error = m.standard_error;
    c.tolerance = o.sigmas * m.standard_error + relative_allowance * std::abs(expected);
    c.passed = std::isfinite(m.mean) && std::isfinite(m.standard_error) &&
               std::abs(m.mean - expected) <= c.tolerance;
    c.detail = std::move(detail);
    auto note = [&](const std::string& why) {
        c.passed = false;
        c.detail = why + (c.detail.empty() ? "" : "; " + c.detail);
    };
    if (expected != 0 && m.standard_error > o.max_relative_standard_error * std::abs(expected))
        note(fmt::format("too noisy to decide: σ = {:.2g} is above {:g}% of the expected value",
                         m.standard_error, 100 * o.max_relative_standard_error));
    if (m.dropped > 0) note(fmt::format("the render dropped {} non-finite samples", m.dropped));
    return c;
}

VerifyCheck judge_rgb(std::string group, std::string name, std::string closed_form, const double expected[3],
                      const Estimate measured[3], double relative_allowance, const VerifyOptions& o,
                      std::string detail) {
    VerifyCheck worst;
    double worst_ratio = -1;
    bool all = true;
    for (int c = 0; c < 3; ++c) {
        VerifyCheck k = judge(group, name, closed_form + " (" + "RGB"[c] + ")", expected[c], measured[c],
                              relative_allowance, o, detail);
        all = all && k.passed;
        double ratio = k.tolerance > 0 ? std::abs(k.measured - k.expected) / k.tolerance
                                       : (k.measured == k.expected ? 0.0 : 1e300);
        if (!std::isfinite(k.measured)) ratio = 1e300;
        if (ratio > worst_ratio) {
            worst_ratio = ratio;
            worst = k;
        }
    }
    worst.passed = all;
    return worst;
}

} // namespace illum
