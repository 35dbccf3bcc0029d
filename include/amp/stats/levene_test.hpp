#pragma once
#include "amp/stats/group_test.hpp"

namespace amp::stats {

// Centre from which Levene's test measures absolute deviations.
enum class LeveneCenter {
  kMedian,  // Brown & Forsythe (1974): robust to the skewed run-cost distributions; the paper's test
  kMean,    // Levene's (1960) original
};

// Levene's test of equal variances: the one-way ANOVA F test on z_ij = |x_ij - centre_i|
// (Glaser 1983). Matches R's car::leveneTest(y ~ g, center = median | mean), i.e.
// anova(lm(abs(y - ave(y, g, FUN = median)) ~ g)). kZeroVariance when every z is constant within
// its group (e.g. every group constant). Throws ParameterError like require_groups.
TestResult levene_test(const Groups& groups, LeveneCenter center = LeveneCenter::kMedian);

}  // namespace amp::stats
