#pragma once
// Shared by planner tests: a returned path joins the problem's first and last seeds and every edge
// re-checks free with an independent checker, at the space's resolution divided by `refinement`.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/counters.hpp"
#include "amp/world/problem.hpp"

namespace amp::test {

inline void expect_valid_path(const world::Problem& p, const std::vector<State>& path, int refinement = 1) {
  ASSERT_GE(path.size(), 2u);
  EXPECT_LT(p.space->distance(path.front(), p.seeds.front()), 1e-9);
  EXPECT_LT(p.space->distance(path.back(), p.seeds.back()), 1e-9);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  State s;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double d = p.space->distance(path[i - 1], path[i]);
    const int n = refinement * std::max(1, static_cast<int>(std::ceil(d / p.space->resolution())));
    for (int j = 0; j <= n; ++j) {
      p.space->interpolate(path[i - 1], path[i], static_cast<double>(j) / n, s);
      ASSERT_TRUE(checker->is_valid(s)) << p.name << ": edge " << i << " step " << j << "/" << n;
    }
  }
}

}  // namespace amp::test
