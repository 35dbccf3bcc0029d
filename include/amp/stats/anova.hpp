#pragma once
#include "amp/stats/group_test.hpp"

namespace amp::stats {

// One-way analysis of variance with pooled error variance (the classic F test for equal means);
// the error mean square and its df also feed the REGWQ critical ranges.
struct AnovaTable {
  double ss_between = 0.0;
  double ss_within = 0.0;
  double df_between = 0.0;  // k - 1
  double df_within = 0.0;   // N - k
  double ms_between = TestResult::kNaN;
  double ms_within = TestResult::kNaN;  // the MSE
  // F = ms_between / ms_within on (df_between, df_within). kTooFewObservations when N == k,
  // kZeroVariance when every group is constant (within-group variation zero to rounding).
  TestResult test;
};

// Matches R's anova(lm(y ~ factor(g))) and oneway.test(y ~ g, var.equal = TRUE).
// Throws ParameterError (via require_groups) for fewer than 2 groups, an empty group or a NaN.
AnovaTable one_way_anova(const Groups& groups);

// True when a sum of squared deviations is zero up to rounding: below n (1e-12 scale)^2, where
// scale is the largest |value| involved. Shared by the F tests so that "constant data" means the
// same thing everywhere.
bool negligible_sum_of_squares(double ss, double n, double scale);

}  // namespace amp::stats
