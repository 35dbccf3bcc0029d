#pragma once
#include "amp/stats/group_test.hpp"

namespace amp::stats {

// Welch's (1951) heteroscedastic one-way ANOVA: compares means without assuming equal variances,
// which run-cost samples rarely have. F on (k - 1, df2) with the Welch-Satterthwaite df2.
// Matches R's oneway.test(y ~ g, var.equal = FALSE).
// kTooFewObservations when a group has fewer than 2 values; kZeroVariance when a group is
// constant (its weight n / s^2 would be infinite). Throws ParameterError like require_groups.
TestResult welch_anova(const Groups& groups);

}  // namespace amp::stats
