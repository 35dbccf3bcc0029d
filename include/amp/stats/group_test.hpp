#pragma once
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

namespace amp::stats {

// Samples of one quantity (e.g. run cost in CD calls) for k planners, one vector per planner.
using Groups = std::vector<std::vector<double>>;

// Why a test could not give a p-value. A degenerate input is a property of the data (every run of
// every planner cost the same), not a user error, so it is reported, never thrown.
enum class TestStatus {
  kOk,
  kZeroVariance,         // the denominator variance is zero: the F/H statistic is 0/0 or x/0
  kTooFewObservations,   // an error degree of freedom is zero, or a group is too small for the test
};

std::string_view to_string(TestStatus s);

// Result of a k-sample test. F tests fill df1 and df2; chi-square tests (Kruskal-Wallis) fill df1
// only. When status != kOk, statistic and p_value are NaN.
struct TestResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double statistic = kNaN;
  double df1 = kNaN;
  double df2 = kNaN;
  double p_value = kNaN;
  TestStatus status = TestStatus::kOk;

  bool ok() const { return status == TestStatus::kOk; }
};

// Throws ParameterError naming `test` unless there are at least two groups, none empty and every
// value finite: the conditions under which a k-sample test is meaningful at all.
void require_groups(const Groups& groups, std::string_view test);

// Total number of observations over all groups.
std::size_t total_count(const Groups& groups);

}  // namespace amp::stats
