#include "amp/stats/regwq.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "amp/core/error.hpp"
#include "amp/stats/anova.hpp"
#include "amp/stats/studentized_range.hpp"

namespace amp::stats {

RegwqResult regwq(const Groups& groups, double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw ParameterError("regwq: alpha: need 0 < alpha < 1, got " + std::to_string(alpha));
  }
  const AnovaTable anova = one_way_anova(groups);  // validates the groups
  const std::size_t k = groups.size();

  RegwqResult r;
  r.mse = anova.ms_within;
  r.df_error = anova.df_within;
  r.status = anova.test.status;
  r.differs.assign(k, std::vector<bool>(k, false));
  r.means.resize(k);
  for (std::size_t i = 0; i < k; ++i) {
    r.means[i] = std::accumulate(groups[i].begin(), groups[i].end(), 0.0) / static_cast<double>(groups[i].size());
  }
  r.order.resize(k);
  std::iota(r.order.begin(), r.order.end(), std::size_t{0});
  std::stable_sort(r.order.begin(), r.order.end(), [&](std::size_t a, std::size_t b) { return r.means[a] < r.means[b]; });
  if (r.status != TestStatus::kOk) return r;

  // covered[lo][hi]: range lo..hi lies inside a range found not significant, so it is not tested.
  std::vector<std::vector<bool>> covered(k, std::vector<bool>(k, false));
  std::vector<std::pair<std::size_t, std::size_t>> homogeneous;
  const auto kd = static_cast<double>(k);
  for (std::size_t p = k; p >= 2; --p) {
    const auto pd = static_cast<double>(p);
    // Ryan's levels as modified by Einot & Gabriel (1975): the two largest ranges use alpha itself.
    const double alpha_p = p + 1 >= k ? alpha : 1.0 - std::pow(1.0 - alpha, pd / kd);
    const double q = studentized_range_quantile(1.0 - alpha_p, static_cast<int>(p), r.df_error);
    for (std::size_t lo = 0; lo + p <= k; ++lo) {
      const std::size_t hi = lo + p - 1;
      if (covered[lo][hi]) continue;
      const std::size_t a = r.order[lo];
      const std::size_t b = r.order[hi];
      RegwqStep s;
      s.lo = lo;
      s.hi = hi;
      s.p = static_cast<int>(p);
      s.alpha_p = alpha_p;
      s.q_critical = q;
      s.range = r.means[b] - r.means[a];
      const double inv_n = 1.0 / static_cast<double>(groups[a].size()) + 1.0 / static_cast<double>(groups[b].size());
      s.critical_range = q * std::sqrt(r.mse / 2.0 * inv_n);  // Tukey-Kramer
      s.significant = s.range > s.critical_range;
      r.steps.push_back(s);
      if (s.significant) {
        r.differs[a][b] = r.differs[b][a] = true;
      } else {
        homogeneous.emplace_back(lo, hi);
        for (std::size_t i = lo; i <= hi; ++i) {
          for (std::size_t j = i; j <= hi; ++j) covered[i][j] = true;
        }
      }
    }
  }
  for (std::size_t i = 0; i < k; ++i) {
    if (!covered[i][i]) homogeneous.emplace_back(i, i);
  }
  std::sort(homogeneous.begin(), homogeneous.end());
  for (const auto& [lo, hi] : homogeneous) {
    std::vector<std::size_t> subset(r.order.begin() + static_cast<std::ptrdiff_t>(lo),
                                    r.order.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
    r.subsets.push_back(std::move(subset));
  }
  return r;
}

}  // namespace amp::stats
