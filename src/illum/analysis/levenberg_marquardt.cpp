#include "illum/analysis/levenberg_marquardt.h"

#include <algorithm>
#include <cmath>

namespace illum {

namespace {

double half_sum_of_squares(const std::vector<double>& r) {
    double s = 0;
    for (double v : r) s += v * v;
    return 0.5 * s;
}

} // namespace

bool cholesky_solve(std::vector<double> a, std::vector<double> b, int n, std::vector<double>* x) {
    // A = L Lᵀ, L stored in the lower triangle of a.
    for (int j = 0; j < n; ++j) {
        double d = a[j * n + j];
        for (int k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
        if (!(d > 0)) return false;
        a[j * n + j] = std::sqrt(d);
        for (int i = j + 1; i < n; ++i) {
            double s = a[i * n + j];
            for (int k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / a[j * n + j];
        }
    }
    for (int i = 0; i < n; ++i) { // L y = b
        for (int k = 0; k < i; ++k) b[i] -= a[i * n + k] * b[k];
        b[i] /= a[i * n + i];
    }
    for (int i = n - 1; i >= 0; --i) { // Lᵀ x = y
        for (int k = i + 1; k < n; ++k) b[i] -= a[k * n + i] * b[k];
        b[i] /= a[i * n + i];
    }
    *x = std::move(b);
    return true;
}

LeastSquaresResult levenberg_marquardt(const LeastSquaresProblem& p, std::vector<double> x,
                                       const LeastSquaresOptions& o) {
    const int n = int(x.size());
    auto clamp_box = [&](std::vector<double>& v) {
        for (int j = 0; j < n; ++j) v[j] = std::clamp(v[j], p.lower[j], p.upper[j]);
    };
    clamp_box(x);
    LeastSquaresResult res;
    std::vector<double> r, rp, rm, trial_r;
    p.residuals(x, r);
    ++res.evaluations;
    const std::size_t m = r.size();
    double cost = half_sum_of_squares(r), lambda = o.initial_lambda;
    std::vector<double> jac(m * std::size_t(n));
    for (res.iterations = 0; res.iterations < o.max_iterations; ++res.iterations) {
        if (p.jacobian) {
            p.jacobian(x, r, jac);
        } else {
            // J by central differences (one-sided at a bound).
            for (int j = 0; j < n; ++j) {
                std::vector<double> xp = x, xm = x;
                xp[j] = std::min(x[j] + p.step[j], p.upper[j]);
                xm[j] = std::max(x[j] - p.step[j], p.lower[j]);
                p.residuals(xp, rp);
                p.residuals(xm, rm);
                res.evaluations += 2;
                double h = xp[j] - xm[j];
                for (std::size_t k = 0; k < m; ++k) jac[k * n + j] = h > 0 ? (rp[k] - rm[k]) / h : 0.0;
            }
        }
        std::vector<double> jtj(std::size_t(n) * n, 0.0), jtr(n, 0.0);
        for (std::size_t k = 0; k < m; ++k) {
            const double* row = &jac[k * n];
            for (int a = 0; a < n; ++a) {
                jtr[a] += row[a] * r[k];
                for (int b = 0; b <= a; ++b) jtj[a * n + b] += row[a] * row[b];
            }
        }
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < a; ++b) jtj[b * n + a] = jtj[a * n + b];
        // A parameter on a bound that the gradient pushes outwards stays there this iteration (its row and
        // column are taken out of the solve), so clamping does not spoil the other parameters' step.
        std::vector<bool> held(std::size_t(n), false);
        for (int a = 0; a < n; ++a)
            held[a] = (x[a] <= p.lower[a] && jtr[a] > 0) || (x[a] >= p.upper[a] && jtr[a] < 0);
        bool improved = false;
        while (lambda < 1e16) {
            std::vector<double> damped = jtj, delta, neg(n);
            for (int a = 0; a < n; ++a) {
                damped[a * n + a] += lambda * std::max(jtj[a * n + a], 1e-30);
                neg[a] = -jtr[a];
            }
            for (int a = 0; a < n; ++a)
                if (held[a]) {
                    for (int b = 0; b < n; ++b) damped[a * n + b] = damped[b * n + a] = 0;
                    damped[a * n + a] = 1;
                    neg[a] = 0;
                }
            if (!cholesky_solve(damped, neg, n, &delta)) {
                lambda *= 4;
                continue;
            }
            std::vector<double> trial = x;
            for (int a = 0; a < n; ++a) trial[a] += delta[a];
            clamp_box(trial);
            p.residuals(trial, trial_r);
            ++res.evaluations;
            double trial_cost = half_sum_of_squares(trial_r);
            if (trial_cost < cost) {
                double step = 0, size = 0;
                for (int a = 0; a < n; ++a) {
                    step += (trial[a] - x[a]) * (trial[a] - x[a]);
                    size += x[a] * x[a];
                }
                double fall = (cost - trial_cost) / std::max(cost, 1e-300);
                x = trial;
                r = trial_r;
                cost = trial_cost;
                lambda = std::max(lambda / 3, 1e-12);
                improved = true;
                if (fall < o.tolerance || std::sqrt(step) < o.tolerance * (std::sqrt(size) + o.tolerance)) {
                    res.converged = true;
                    res.stop = fall < o.tolerance ? "cost no longer falls" : "step below tolerance";
                }
                break;
            }
            lambda *= 4;
        }
        if (!improved) {
            res.converged = true;
            res.stop = "no step lowers the cost (a minimum within the box)";
        }
        if (res.converged) {
            ++res.iterations;
            break;
        }
    }
    if (!res.converged) res.stop = "iteration limit";
    res.x = x;
    res.cost = cost;
    return res;
}

} // namespace illum
