#pragma once

namespace amp::stats {

// The studentized range distribution: Q = (max - min of k iid N(0,1)) / S, with nu * S^2 ~ chi2(nu)
// independent of the normals (Tukey's q; one range, R's nranges = 1). Used for the critical ranges
// of the REGWQ procedure.
//
// The cdf is the double integral of Copenhaver & Holland (1988),
//   P(Q <= q) = int_0^inf f_S(s) W(q s) ds,   W(w) = k int phi(z) [Phi(z + w) - Phi(z)]^(k-1) dz,
// evaluated by composite Gauss-Legendre (inner) and adaptive Gauss-Kronrod (outer) quadrature;
// absolute error ~1e-10. df may be +infinity (S = 1). Matches R's ptukey(q, k, df).
//
// Throws ParameterError for k < 2, df < 1 or NaN arguments.
double studentized_range_cdf(double q, int k, double df);

// The q with studentized_range_cdf(q, k, df) = p, found by bracketing and TOMS 748 root finding on
// the cdf (relative error ~1e-11 in q, finer than R's qtukey, which stops at |dq| < 1e-4).
// p = 0 gives 0 and p = 1 gives +infinity. Throws ParameterError for p outside [0, 1].
double studentized_range_quantile(double p, int k, double df);

}  // namespace amp::stats
