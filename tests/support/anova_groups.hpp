#pragma once
// Shared by the ANOVA tests (tests/stats/anova_test.cpp, welch_anova_test.cpp): groups whose test
// statistics were computed in R (the R lines are quoted beside each expected figure).
#include <cmath>

#include "amp/stats/group_test.hpp"

namespace amp::stats::test {

// R: g1, g2, g3 below; y <- c(g1, g2, g3); g <- factor(rep(1:3, c(8, 7, 9)))
inline const Groups kGroups = {
    {12.1, 15.3, 9.8, 22.4, 13.0, 17.7, 11.2, 30.5},
    {8.4, 9.1, 7.7, 12.6, 10.2, 9.9, 8.8},
    {14.2, 25.8, 19.9, 41.3, 16.6, 21.0, 18.4, 28.7, 35.2},
};

inline Groups cost_groups() {
  // R: cost <- function(gr, i) 1000 * exp(1.5 * sin(1.3 * i + gr) + 0.4 * gr * cos(0.7 * i)); 0:239
  Groups g(3);
  for (int gr = 1; gr <= 3; ++gr) {
    for (int i = 0; i < 240; ++i) g[gr - 1].push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + gr) + 0.4 * gr * std::cos(0.7 * i)));
  }
  return g;
}

}  // namespace amp::stats::test
