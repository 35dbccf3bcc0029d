#include "amp/stats/anova.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/fisher_f.hpp>

namespace amp::stats {
namespace {

// Relative size below which a deviation is taken for rounding noise of the mean.
constexpr double kRelativeRounding = 1e-12;

}  // namespace

bool negligible_sum_of_squares(double ss, double n, double scale) {
  const double noise = kRelativeRounding * scale;
  return ss <= n * noise * noise;
}

AnovaTable one_way_anova(const Groups& groups) {
  require_groups(groups, "one_way_anova");
  const auto n_total = static_cast<double>(total_count(groups));
  const auto k = static_cast<double>(groups.size());

  double grand_sum = 0.0;
  double scale = 0.0;
  for (const auto& g : groups) {
    for (double v : g) {
      grand_sum += v;
      scale = std::max(scale, std::abs(v));
    }
  }
  const double grand_mean = grand_sum / n_total;

  AnovaTable t;
  for (const auto& g : groups) {
    double sum = 0.0;
    for (double v : g) sum += v;
    const double mean = sum / static_cast<double>(g.size());
    for (double v : g) t.ss_within += (v - mean) * (v - mean);
    t.ss_between += static_cast<double>(g.size()) * (mean - grand_mean) * (mean - grand_mean);
  }
  t.df_between = k - 1.0;
  t.df_within = n_total - k;
  t.test.df1 = t.df_between;
  t.test.df2 = t.df_within;
  t.ms_between = t.ss_between / t.df_between;
  if (t.df_within < 1.0) {
    t.test.status = TestStatus::kTooFewObservations;
    return t;
  }
  t.ms_within = t.ss_within / t.df_within;
  if (negligible_sum_of_squares(t.ss_within, n_total, scale)) {
    t.test.status = TestStatus::kZeroVariance;
    return t;
  }
  t.test.statistic = t.ms_between / t.ms_within;
  const boost::math::fisher_f f(t.df_between, t.df_within);
  t.test.p_value = boost::math::cdf(boost::math::complement(f, t.test.statistic));
  return t;
}

}  // namespace amp::stats
