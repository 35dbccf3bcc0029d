#pragma once
#include <cstddef>
#include <limits>
#include <optional>
#include <span>

namespace amp::stats {

// Descriptive statistics of one planner's run costs, the columns of the paper's Table 1 plus the
// five-number summary drawn in box plots. With n = 0 every field but n is NaN; with n = 1 the
// standard deviation and the coefficient of variation are NaN (as R's sd()).
struct Summary {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::size_t n = 0;
  double mean = kNaN;
  double std_dev = kNaN;     // sample standard deviation (divisor n - 1)
  double cv_percent = kNaN;  // 100 * std_dev / mean, as in Table 1; NaN when mean == 0
  double min = kNaN;
  double q1 = kNaN;          // quartiles by quantile() below (R's default, type 7)
  double median = kNaN;
  double q3 = kNaN;
  double max = kNaN;
  // Student's t 95% confidence interval of the mean, mean -+ t(0.975, n - 1) std_dev / sqrt(n), as R's
  // t.test(x)$conf.int; NaN for n < 2.
  double ci95_low = kNaN;
  double ci95_high = kNaN;
};

// Throws ParameterError if a value is not finite.
Summary describe(std::span<const double> x);

// Quantile of `sorted` (ascending) at probability prob in [0, 1], Hyndman & Fan (1996) type 7,
// R's default: linear interpolation between order statistics at h = (n - 1) prob.
// Throws ParameterError for an empty sample or prob outside [0, 1].
double quantile(std::span<const double> sorted, double prob);

// The type-7 median of an unsorted sample (quantile at 0.5); none for an empty sample, which has no
// median (a record writes it as null, a table of numbers leaves it out).
std::optional<double> median(std::span<const double> sample);

}  // namespace amp::stats
