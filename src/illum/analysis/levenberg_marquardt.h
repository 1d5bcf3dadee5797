// Levenberg-Marquardt for box-constrained nonlinear least squares: minimise C(x) = ½ Σ r_k(x)² over
// x in [lower, upper]. Each iteration solves Marquardt's damped normal equations (Marquardt 1963, "An
// Algorithm for Least-Squares Estimation of Nonlinear Parameters", eq. 31, the diagonal scaling)
//   (JᵀJ + λ diag(JᵀJ)) δ = -Jᵀr
// by Cholesky, with J given or from central differences, and clamps x + δ to the box; a parameter on a
// bound that the gradient pushes outwards is held there for the iteration. A step that lowers C is taken
// and λ divided by 3; otherwise λ is multiplied by 4 and the step retried. It stops when C falls by less
// than `tolerance` relative, when the step is below `tolerance` relative to x, when no step lowers C, or
// after max_iterations.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace illum {

struct LeastSquaresProblem {
    // r(x): fills `residuals` (always the same count for every x).
    std::function<void(const std::vector<double>& x, std::vector<double>& residuals)> residuals;
    std::vector<double> lower, upper;
    // The Jacobian J[k n + j] = ∂r_k/∂x_j at x (r: the residuals there), when the problem knows it;
    // otherwise central differences with `step`.
    std::function<void(const std::vector<double>& x, const std::vector<double>& r,
                       std::vector<double>& jacobian)>
        jacobian;
    // Central-difference step for each parameter (absolute).
    std::vector<double> step;
};

struct LeastSquaresOptions {
    int max_iterations = 200;
    double tolerance = 1e-10;
    double initial_lambda = 1e-3;
};

struct LeastSquaresResult {
    std::vector<double> x;
    double cost = 0; // ½ Σ r²
    int iterations = 0, evaluations = 0;
    bool converged = false;
    std::string stop; // why it stopped
};

LeastSquaresResult levenberg_marquardt(const LeastSquaresProblem& problem, std::vector<double> x0,
                                       const LeastSquaresOptions& options = {});

// Solves A x = b for a symmetric positive definite n x n A (row-major) by Cholesky; false when A is not
// positive definite.
bool cholesky_solve(std::vector<double> a, std::vector<double> b, int n, std::vector<double>* x);

} // namespace illum
