// Statistics for sampling tests: running mean with standard error, and Pearson's chi-square test.
#pragma once

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

// Regularised upper incomplete gamma function Q(a, x) = Γ(a, x) / Γ(a): the series of P = 1 - Q for
// x < a + 1 and the continued fraction of Q otherwise (modified Lentz); both are textbook expansions
// (Abramowitz & Stegun 6.5.29 and 6.5.31).
inline double gamma_q(double a, double x) {
    if (x <= 0) return 1;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-16) break;
        }
        return std::max(0.0, 1 - sum * std::exp(log_prefix));
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

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
