#pragma once
// Shared by planner tests: a returned path joins the problem's first and last seeds and every edge
// re-checks free with an independent checker, at the space's resolution divided by `refinement`.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/counters.hpp"
#include "amp/core/edge_steps.hpp"
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
    const std::int64_t segments = core::edge_segments(d, p.space->resolution());
    ASSERT_GT(segments, 0) << p.name << ": edge " << i << " has too many steps to check";
    const std::int64_t n = refinement * segments;
    for (std::int64_t j = 0; j <= n; ++j) {
      p.space->interpolate(path[i - 1], path[i], static_cast<double>(j) / static_cast<double>(n), s);
      ASSERT_TRUE(checker->is_valid(s)) << p.name << ": edge " << i << " step " << j << "/" << n;
    }
  }
}

}  // namespace amp::test
