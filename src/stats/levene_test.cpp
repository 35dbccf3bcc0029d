#include "amp/stats/levene_test.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "amp/stats/anova.hpp"
#include "amp/stats/descriptive.hpp"

namespace amp::stats {

TestResult levene_test(const Groups& groups, LeveneCenter center) {
  require_groups(groups, "levene_test");
  Groups deviations(groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const auto& g = groups[i];
    double c = 0.0;
    if (center == LeveneCenter::kMedian) {
      std::vector<double> sorted(g);
      std::sort(sorted.begin(), sorted.end());
      c = quantile(sorted, 0.5);
    } else {
      for (double v : g) c += v;
      c /= static_cast<double>(g.size());
    }
    deviations[i].reserve(g.size());
    for (double v : g) deviations[i].push_back(std::abs(v - c));
  }
  return one_way_anova(deviations).test;
}

}  // namespace amp::stats
