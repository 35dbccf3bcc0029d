#pragma once
#include <span>

namespace amp::learn {

// The Kolmogorov distribution and the one-sample Kolmogorov-Smirnov test (used by PG-means).
//
// K(x) = P(sup_t |B(t)| <= x) for a Brownian bridge B: the limit law of sqrt(n) D_n. Computed by
// its two series (Boost has none):
//   x <  1.18:  K(x) = sqrt(2 pi) / x * sum_{k>=1} exp(-(2k-1)^2 pi^2 / (8 x^2))
//   x >= 1.18:  K(x) = 1 - 2 sum_{k>=1} (-1)^(k-1) exp(-2 k^2 x^2)
// each summed until a term drops below 1e-17 of the sum (a handful of terms on either side of the
// switch point, where both converge fast). K(x) = 0 for x <= 0.
double kolmogorov_cdf(double x);

// 1 - K(x), from the second series directly where it is small (no cancellation in the tail).
double kolmogorov_sf(double x);

// The x with K(x) = p, by bisection to double precision; p = 0 gives 0, p = 1 gives +infinity.
// Throws ParameterError for p outside [0, 1].
double kolmogorov_quantile(double p);

// The KS statistic D_n = sup_x |F_n(x) - F(x)| of a sample, given F at the sample's values in
// ascending order: D_n = max_i max(i/n - F(x_(i)), F(x_(i)) - (i-1)/n), i = 1..n.
double ks_statistic(std::span<const double> sorted_model_cdf);

// Stephens' (1970) finite-n scaling: sqrt(n) + 0.12 + 0.11 / sqrt(n). With it, P(D_n > x / s(n)) is
// close to 1 - K(x) already for n >= 5 (R's ks.test uses plain sqrt(n) in its asymptotic case).
double stephens_scale(int n);

// The asymptotic p-value of D_n with Stephens' scaling: 1 - K(stephens_scale(n) * d).
double ks_p_value(double d, int n);

// The critical value of D_n at level alpha: K^-1(1 - alpha) / stephens_scale(n).
double ks_critical_value(int n, double alpha);

}  // namespace amp::learn
