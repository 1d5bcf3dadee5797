#include "illum/analysis/stats.h"

#include <cmath>
#include <limits>

namespace illum {

namespace {
// Series γ(a,x) = e^-x x^a Σ x^n / (a (a+1) ... (a+n)), good for x < a + 1.
double gamma_p_series(double a, double x) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}
// Continued fraction for Γ(a,x), evaluated by the modified Lentz method; good for x >= a + 1.
double gamma_q_fraction(double a, double x) {
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
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}
} // namespace

double regularized_gamma_p(double a, double x) {
    if (!(a > 0) || !(x >= 0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0) return 0;
    if (x < a + 1) return gamma_p_series(a, x);
    return 1 - gamma_q_fraction(a, x);
}

double regularized_gamma_q(double a, double x) {
    if (!(a > 0) || !(x >= 0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0) return 1;
    if (x < a + 1) return 1 - gamma_p_series(a, x);
    return gamma_q_fraction(a, x);
}

double chi_square_survival(double x, double dof) { return regularized_gamma_q(dof / 2, x / 2); }

double sidak_significance(double alpha, int m) { return m <= 1 ? alpha : 1 - std::pow(1 - alpha, 1.0 / m); }

} // namespace illum
