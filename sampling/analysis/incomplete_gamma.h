#pragma once
// Regularized incomplete gamma functions P(a,x) and Q(a,x) = 1 - P(a,x), for the chi-square
// p-value: Pr[X >= x] = Q(k/2, x/2) for k degrees of freedom.
namespace pdrt {

// Q(a, x) = Gamma(a, x) / Gamma(a), for a > 0, x >= 0. Series for x < a + 1, Lentz's continued
// fraction otherwise (so a tiny Q is computed directly, not as 1 - P).
double regularized_gamma_q(double a, double x);

// P(a, x) = 1 - Q(a, x).
double regularized_gamma_p(double a, double x);

// Upper-tail p-value of a chi-square statistic with `dof` degrees of freedom.
double chi_square_p_value(double statistic, double dof);

}  // namespace pdrt
