#include "amp/stats/welch_anova.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/distributions/fisher_f.hpp>

#include "amp/stats/anova.hpp"

namespace amp::stats {

TestResult welch_anova(const Groups& groups) {
  require_groups(groups, "welch_anova");
  const auto k = static_cast<double>(groups.size());
  TestResult r;
  r.df1 = k - 1.0;

  std::vector<double> weight(groups.size());
  std::vector<double> mean(groups.size());
  std::vector<double> size(groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const auto& g = groups[i];
    size[i] = static_cast<double>(g.size());
    if (g.size() < 2) {
      r.status = TestStatus::kTooFewObservations;
      return r;
    }
    double sum = 0.0;
    double scale = 0.0;
    for (double v : g) {
      sum += v;
      scale = std::max(scale, std::abs(v));
    }
    mean[i] = sum / size[i];
    double ss = 0.0;
    for (double v : g) ss += (v - mean[i]) * (v - mean[i]);
    if (negligible_sum_of_squares(ss, size[i], scale)) {
      r.status = TestStatus::kZeroVariance;
      return r;
    }
    weight[i] = size[i] / (ss / (size[i] - 1.0));  // n_i / s_i^2
  }

  double weight_sum = 0.0;
  double weighted_mean = 0.0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    weight_sum += weight[i];
    weighted_mean += weight[i] * mean[i];
  }
  weighted_mean /= weight_sum;
  double between = 0.0;
  double lambda = 0.0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    between += weight[i] * (mean[i] - weighted_mean) * (mean[i] - weighted_mean);
    const double share = 1.0 - weight[i] / weight_sum;
    lambda += share * share / (size[i] - 1.0);
  }
  lambda /= k * k - 1.0;
  r.statistic = (between / (k - 1.0)) / (1.0 + 2.0 * (k - 2.0) * lambda);
  r.df2 = 1.0 / (3.0 * lambda);
  const boost::math::fisher_f f(r.df1, r.df2);
  r.p_value = boost::math::cdf(boost::math::complement(f, r.statistic));
  return r;
}

}  // namespace amp::stats
