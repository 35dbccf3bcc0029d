#pragma once
#include <cstddef>
#include <vector>

#include "amp/stats/group_test.hpp"

namespace amp::stats {

// One range of ordered means tested by REGWQ: positions lo..hi (0-based, ascending mean order)
// span p = hi - lo + 1 means.
struct RegwqStep {
  std::size_t lo = 0;
  std::size_t hi = 0;
  int p = 0;
  double alpha_p = 0.0;         // per-range level
  double q_critical = 0.0;      // studentized range quantile q(1 - alpha_p; p, df_error)
  double range = 0.0;           // mean[hi] - mean[lo]
  double critical_range = 0.0;  // q_critical * sqrt(MSE / 2 * (1 / n_lo + 1 / n_hi))
  bool significant = false;     // range > critical_range
};

struct RegwqResult {
  std::vector<std::size_t> order;  // group indices by ascending mean (ties by index)
  std::vector<double> means;       // per group, original index
  // Homogeneous subsets, as SPSS prints them: maximal runs of ordered means whose range was not
  // declared significant (group indices, ascending mean), listed by first member; subsets may
  // overlap. A group in no such run is a subset of its own.
  std::vector<std::vector<std::size_t>> subsets;
  std::vector<RegwqStep> steps;    // every range actually tested, in testing order
  double mse = TestResult::kNaN;
  double df_error = TestResult::kNaN;
  // differs[a][b]: groups a and b (original indices) differ significantly; symmetric, k x k.
  std::vector<std::vector<bool>> differs;
  // Not kOk when the ANOVA error term is degenerate (zero MSE or df); then nothing is tested, no
  // pair differs and subsets is empty.
  TestStatus status = TestStatus::kOk;
};

// The Ryan-Einot-Gabriel-Welsch multiple-range procedure on the studentized range (REGWQ; Einot &
// Gabriel 1975), at experimentwise level alpha (the paper uses 0.01). Step-down over ranges of
// p = k, k-1, ..., 2 ordered means at level alpha_p = 1 - (1 - alpha)^(p/k) for p < k-1 and alpha
// for p >= k-1; a range inside a non-significant range is not tested. Unequal group sizes use the
// Tukey-Kramer standard error. The MSE and df come from one_way_anova().
// Throws ParameterError for alpha outside (0, 1) or groups rejected by require_groups.
RegwqResult regwq(const Groups& groups, double alpha = 0.01);

}  // namespace amp::stats
