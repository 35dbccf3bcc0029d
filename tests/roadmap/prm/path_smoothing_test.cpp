#include "amp/roadmap/prm/path_smoothing.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

using test::state2;

TEST(PathSmoothing, PathLengthByHand) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  EXPECT_DOUBLE_EQ(path_length(space, {}), 0.0);
  EXPECT_DOUBLE_EQ(path_length(space, {state2(1, 1)}), 0.0);
  EXPECT_DOUBLE_EQ(path_length(space, {state2(0, 0), state2(3, 4), state2(3, 5)}), 6.0);
}

TEST(PathSmoothing, ShortcutsAZigzagInFreeSpace) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  test::BoxEnvironment env({}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);
  std::vector<State> path;
  for (int i = 0; i <= 8; ++i) path.push_back(state2(1 + i, i % 2 == 0 ? 2 : 4));
  core::Rng rng(1);
  const int taken = shortcut_path(lp, rng, 200, path);
  EXPECT_GT(taken, 0);
  ASSERT_EQ(path.size(), 2u);  // free space: ends up as the straight segment
  EXPECT_EQ(path.front(), state2(1, 2));
  EXPECT_EQ(path.back(), state2(9, 2));
}

TEST(PathSmoothing, KeepsTheDetourAroundAWall) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  test::BoxEnvironment env({{4.5, 0.0, 5.5, 6.0}}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  StraightLinePlanner lp(space, *checker);
  std::vector<State> path = {state2(1, 1), state2(2, 7), state2(5, 8), state2(8, 7), state2(9, 1)};
  core::Rng rng(2);
  shortcut_path(lp, rng, 100, path);
  ASSERT_GE(path.size(), 3u);
  EXPECT_EQ(path.front(), state2(1, 1));
  EXPECT_EQ(path.back(), state2(9, 1));
  for (std::size_t i = 1; i < path.size(); ++i) EXPECT_TRUE(lp.connect(path[i - 1], path[i]));
}

}  // namespace
}  // namespace amp::roadmap
