#pragma once
#include <span>
#include <vector>

#include "amp/stats/group_test.hpp"

namespace amp::stats {

// Ranks 1..n of x, ties given the average of the ranks they span (R's rank(ties.method = "average")).
std::vector<double> average_ranks(std::span<const double> x);

// Kruskal & Wallis (1952) rank test that the groups come from one distribution: the rank-based
// check beside the ANOVA, insensitive to the heavy right tail of run costs. H is divided by the tie
// correction 1 - sum(t^3 - t) / (N^3 - N); p from chi2(k - 1). Matches R's kruskal.test.
// kZeroVariance when all values are tied. Throws ParameterError like require_groups.
TestResult kruskal_wallis(const Groups& groups);

}  // namespace amp::stats
