#include "amp/roadmap/local_planners/straight_line_planner.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

using test::Box;
using test::BoxEnvironment;
using test::RobotKind;
using test::state2;

TEST(StraightLinePlanner, BisectionOrderByHand) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  core::Counters counters;
  BoxEnvironment env({}, RobotKind::kPoint);
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);
  EXPECT_EQ(lp.bisection_order(8), (std::vector<int>{4, 2, 6, 1, 3, 5, 7}));
  EXPECT_EQ(lp.bisection_order(5), (std::vector<int>{2, 1, 3, 4}));
  EXPECT_EQ(lp.bisection_order(2), (std::vector<int>{1}));
  EXPECT_TRUE(lp.bisection_order(1).empty());
}

TEST(StraightLinePlanner, ChecksEveryStateAtResolutionInBisectionOrder) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  std::vector<State> record;
  BoxEnvironment env({}, RobotKind::kPoint);
  env.set_record(&record);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);

  const State a = state2(1, 1), b = state2(7, 9);  // length 10
  const int n = static_cast<int>(std::ceil(10.0 / space.resolution()));  // resolution = 0.01 * 10 sqrt 2
  ASSERT_TRUE(lp.connect(a, b));
  ASSERT_EQ(record.size(), static_cast<std::size_t>(n - 1));
  EXPECT_EQ(counters.cd_calls(), static_cast<std::uint64_t>(n - 1));
  EXPECT_EQ(counters.lp_calls(), 1u);
  EXPECT_EQ(counters.lp_successes(), 1u);
  // Each check is the state at t = i / n with i in bisection order.
  std::vector<int> steps;
  for (const State& s : record) {
    const double t = (s[0] - 1.0) / 6.0;
    const int i = static_cast<int>(std::lround(t * n));
    EXPECT_NEAR(t, static_cast<double>(i) / n, 1e-12);
    EXPECT_NEAR(s[1], 1.0 + 8.0 * i / n, 1e-12);
    steps.push_back(i);
  }
  EXPECT_EQ(steps.front(), n / 2);  // midpoint first
  // The first checks halve the gaps: after 2^j - 1 checks no unchecked run is longer than n / 2^j.
  for (std::size_t checks : {1u, 3u, 7u, 15u}) {
    std::vector<int> seen(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(checks));
    seen.push_back(0);
    seen.push_back(n);
    std::sort(seen.begin(), seen.end());
    int gap = 0;
    for (std::size_t i = 1; i < seen.size(); ++i) gap = std::max(gap, seen[i] - seen[i - 1]);
    EXPECT_LE(gap, n / static_cast<int>(checks + 1) + 1) << checks;
  }
  std::sort(steps.begin(), steps.end());
  for (int i = 1; i < n; ++i) EXPECT_EQ(steps[i - 1], i);  // every interior state exactly once
}

TEST(StraightLinePlanner, FailsOnAThinWallAndStopsEarly) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  // Thicker than the resolution (0.1414) but far thinner than the edge.
  BoxEnvironment env({{4.9, 0.0, 5.05, 10.0}}, RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);
  EXPECT_FALSE(lp.connect(state2(1, 5), state2(9, 5.3)));
  const int n = static_cast<int>(std::ceil(space.distance(state2(1, 5), state2(9, 5.3)) / space.resolution()));
  EXPECT_LT(counters.cd_calls(), static_cast<std::uint64_t>(n - 1));  // did not check every state
  EXPECT_EQ(counters.lp_calls(), 1u);
  EXPECT_EQ(counters.lp_successes(), 0u);
  // The same wall is missed by neither direction, and a parallel edge beside it is free.
  EXPECT_FALSE(lp.connect(state2(9, 5.3), state2(1, 5)));
  EXPECT_TRUE(lp.connect(state2(1, 5), state2(4.8, 9)));
}

TEST(StraightLinePlanner, ShortEdgeNeedsNoCheck) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  BoxEnvironment env({}, RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);
  EXPECT_TRUE(lp.connect(state2(1, 1), state2(1.05, 1)));  // one segment: endpoints only
  EXPECT_EQ(counters.cd_calls(), 0u);
}

}  // namespace
}  // namespace amp::roadmap
