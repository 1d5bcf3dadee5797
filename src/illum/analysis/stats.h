// Statistics for the BSDF audits: the regularised incomplete gamma function and the chi-square
// distribution's upper tail, written from their series and continued-fraction expansions
// (Abramowitz & Stegun 6.5.29 and 6.5.31).
#pragma once

namespace illum {

// P(a, x) = γ(a, x) / Γ(a) and Q(a, x) = 1 - P(a, x), for a > 0, x >= 0.
double regularized_gamma_p(double a, double x);
double regularized_gamma_q(double a, double x);
// Upper tail probability of the chi-square distribution with k degrees of freedom: Q(k/2, x/2).
double chi_square_survival(double x, double dof);
// Per-test significance for m tests at family-wise level alpha (Sidak): 1 - (1 - alpha)^(1/m).
double sidak_significance(double alpha, int m);

} // namespace illum
