// Statistics for sampling tests: running mean with standard error, and Pearson's chi-square test.
#pragma once

#include "illum/analysis/stats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

namespace illum::test {

// Welford's running mean and variance.
struct MeanAccumulator {
    long long n = 0;
    double mean = 0, m2 = 0;
    void add(double x) {
        ++n;
        double d = x - mean;
        mean += d / double(n);
        m2 += d * (x - mean);
    }
    double variance() const { return n > 1 ? m2 / double(n - 1) : 0; }
    // Standard error of the mean.
    double std_error() const { return n > 0 ? std::sqrt(variance() / double(n)) : 0; }
};

// Regularised upper incomplete gamma function Q(a, x), the chi-square survival function's core: the
// library's (analysis/stats.h), so the known-value checks in warp_test.cpp test it.
inline double gamma_q(double a, double x) { return regularized_gamma_q(a, x); }

struct Chi2Result {
    double statistic = 0;
    int dof = 0;
    double p_value = 1;
};

// Pearson's chi-square goodness of fit of observed counts to expected counts. Bins expected to hold fewer
// than min_expected samples are pooled into one bin (merged into the smallest other bin if the pool is
// still small), the usual condition for the chi-square approximation. A sample in a bin of expected count
// zero gives p = 0.
inline Chi2Result chi2_test(std::span<const double> observed, std::span<const double> expected,
                            double min_expected = 5) {
    std::vector<std::pair<double, double>> bins; // (expected, observed)
    double pool_e = 0, pool_o = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0) {
            if (observed[i] > 0) return {std::numeric_limits<double>::infinity(), 0, 0};
            continue;
        }
        if (expected[i] < min_expected) {
            pool_e += expected[i];
            pool_o += observed[i];
        } else {
            bins.emplace_back(expected[i], observed[i]);
        }
    }
    if (pool_e > 0) {
        if (pool_e >= min_expected || bins.empty()) {
            bins.emplace_back(pool_e, pool_o);
        } else {
            auto it = std::min_element(bins.begin(), bins.end());
            it->first += pool_e;
            it->second += pool_o;
        }
    }
    Chi2Result r;
    for (auto [e, o] : bins) r.statistic += (o - e) * (o - e) / e;
    r.dof = int(bins.size()) - 1;
    r.p_value = r.dof > 0 ? gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
    return r;
}

} // namespace illum::test
