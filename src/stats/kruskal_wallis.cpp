#include "amp/stats/kruskal_wallis.hpp"

#include <algorithm>
#include <numeric>

#include <boost/math/distributions/chi_squared.hpp>

namespace amp::stats {

std::vector<double> average_ranks(std::span<const double> x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> ranks(x.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && x[order[j + 1]] == x[order[i]]) ++j;
    const double rank = 0.5 * static_cast<double>(i + j) + 1.0;  // mean of ranks i+1 .. j+1
    for (std::size_t m = i; m <= j; ++m) ranks[order[m]] = rank;
    i = j + 1;
  }
  return ranks;
}

TestResult kruskal_wallis(const Groups& groups) {
  require_groups(groups, "kruskal_wallis");
  std::vector<double> pooled;
  pooled.reserve(total_count(groups));
  for (const auto& g : groups) pooled.insert(pooled.end(), g.begin(), g.end());
  const std::vector<double> ranks = average_ranks(pooled);
  const auto n = static_cast<double>(pooled.size());

  TestResult r;
  r.df1 = static_cast<double>(groups.size()) - 1.0;
  // Tie correction: each run of t equal values lowers the rank variance by (t^3 - t) / 12.
  std::vector<double> sorted_ranks(ranks);
  std::sort(sorted_ranks.begin(), sorted_ranks.end());
  double ties = 0.0;
  for (std::size_t i = 0; i < sorted_ranks.size();) {
    std::size_t j = i;
    while (j + 1 < sorted_ranks.size() && sorted_ranks[j + 1] == sorted_ranks[i]) ++j;
    const auto t = static_cast<double>(j - i + 1);
    ties += t * t * t - t;
    i = j + 1;
  }
  const double correction = 1.0 - ties / (n * n * n - n);
  if (!(correction > 0.0)) {  // every value tied (or N = 1): no rank information at all
    r.status = TestStatus::kZeroVariance;
    return r;
  }
  double sum_sq = 0.0;
  std::size_t offset = 0;
  for (const auto& g : groups) {
    double rank_sum = 0.0;
    for (std::size_t i = 0; i < g.size(); ++i) rank_sum += ranks[offset + i];
    offset += g.size();
    sum_sq += rank_sum * rank_sum / static_cast<double>(g.size());
  }
  r.statistic = (12.0 * sum_sq / (n * (n + 1.0)) - 3.0 * (n + 1.0)) / correction;
  const boost::math::chi_squared chi(r.df1);
  r.p_value = boost::math::cdf(boost::math::complement(chi, std::max(0.0, r.statistic)));
  return r;
}

}  // namespace amp::stats
