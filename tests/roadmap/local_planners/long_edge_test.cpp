// Edges whose step count does not fit an int (or anything): the straight-line planner and the grid
// A* count them in 64 bits, refuse what cannot be counted, and stop inside one edge when the run's
// stop condition fires, never reporting a refused edge free.
#include <chrono>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/edge_steps.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/competence/grid_astar_planner.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

using test::BoxEnvironment;
using test::RobotKind;
using test::state2;

constexpr std::size_t kNoNodeLimit = std::numeric_limits<std::size_t>::max();

// [0,10]^2 with a wall at x in [4.5, 5.5]: an edge from x = 1 to x = 9 crosses it.
struct WallWorld {
  core::JointSpace space = core::make_rn_space({0, 0}, {10, 10});
  BoxEnvironment env{{{4.5, 0.0, 5.5, 10.0}}, RobotKind::kPoint};
  core::Counters counters;
  std::unique_ptr<world::ValidityChecker> checker = env.make_checker(counters);
};

TEST(LongEdge, GeneratorMatchesTheBreadthFirstOrder) {
  WallWorld w;
  StraightLinePlanner lp(w.space, *w.checker);
  for (int n = 0; n <= 700; ++n) {
    std::vector<int> generated;
    StraightLinePlanner::for_each_bisection_step(n, [&](std::int64_t i) {
      generated.push_back(static_cast<int>(i));
      return true;
    });
    ASSERT_EQ(generated, lp.bisection_order(n)) << n;
  }
  for (const int n : {4096, 4097, 65535, 65537}) {
    std::vector<int> generated;
    StraightLinePlanner::for_each_bisection_step(n, [&](std::int64_t i) {
      generated.push_back(static_cast<int>(i));
      return true;
    });
    ASSERT_EQ(generated, lp.bisection_order(n)) << n;
  }
}

TEST(LongEdge, GeneratorHalvesAnEdgeOf2To50Segments) {
  constexpr std::int64_t n = std::int64_t{1} << 50;
  std::vector<std::int64_t> first;
  const bool finished = StraightLinePlanner::for_each_bisection_step(n, [&](std::int64_t i) {
    first.push_back(i);
    return first.size() < 7;
  });
  EXPECT_FALSE(finished);
  EXPECT_EQ(first, (std::vector<std::int64_t>{n / 2, n / 4, 3 * (n / 4), n / 8, 3 * (n / 8), 5 * (n / 8),
                                              7 * (n / 8)}));
}

TEST(LongEdge, AnEdgeOfEightBillionStepsStillFindsTheWall) {
  WallWorld w;
  w.space.set_resolution(1e-9);  // 8 / 1e-9 = 8e9 segments: an int cast once wrapped to 1 and passed
  StraightLinePlanner lp(w.space, *w.checker);
  EXPECT_FALSE(lp.connect(state2(1, 5), state2(9, 5)));
  EXPECT_GT(w.counters.cd_calls(), 0u);
  EXPECT_LT(w.counters.cd_calls(), 100u);  // bisection reaches the 1-wide wall within a few levels
}

TEST(LongEdge, AnUncountableEdgeIsRefusedWithoutACheck) {
  WallWorld w;
  w.space.set_resolution(1e-300);
  StraightLinePlanner lp(w.space, *w.checker);
  EXPECT_FALSE(lp.connect(state2(1, 1), state2(2, 1)));  // free, but 10^300 steps cannot be checked
  EXPECT_EQ(w.counters.cd_calls(), 0u);
  EXPECT_EQ(w.counters.lp_calls(), 1u);
  EXPECT_EQ(w.counters.lp_successes(), 0u);
}

TEST(LongEdge, AFreeEdgeOfBillionsOfStepsStopsAtTheTimeLimit) {
  WallWorld w;
  w.space.set_resolution(1e-10);  // a free edge of 2e10 states: hours of CD calls
  const core::StopCondition stop(0.05, kNoNodeLimit);
  StraightLinePlanner lp(w.space, *w.checker, &stop);
  EXPECT_FALSE(lp.connect(state2(1, 1), state2(3, 1)));
  EXPECT_TRUE(stop.fired());
  EXPECT_EQ(stop.check(0), core::StopReason::kTimeLimit);  // the planner's loop sees why
  EXPECT_LT(w.counters.cd_calls(), 20000000000u);
  // Once fired, edges are refused before their first CD call.
  const std::uint64_t calls = w.counters.cd_calls();
  EXPECT_FALSE(lp.connect(state2(1, 1), state2(1.5, 1)));
  EXPECT_EQ(w.counters.cd_calls(), calls);
}

TEST(LongEdge, ShortEdgesAfterTheDeadlineAreStoppedWithinOneStride) {
  WallWorld w;  // resolution 0.141: an edge of length 1.3 checks 9 states
  const core::StopCondition stop(0.01, kNoNodeLimit);
  StraightLinePlanner lp(w.space, *w.checker, &stop);
  EXPECT_TRUE(lp.connect(state2(1, 1), state2(2, 2)));
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  // The poll counts CD calls across edges, so a loop of short edges (smoothing, a lazy path check)
  // that never checks the stop itself still ends.
  int accepted = 0;
  while (lp.connect(state2(1, 1), state2(2, 2))) ASSERT_LE(++accepted, static_cast<int>(core::StopPoll::kStride));
  EXPECT_TRUE(stop.fired());
}

TEST(LongEdge, WithoutAStopConditionAnEdgeIsCheckedInFull) {
  WallWorld w;
  w.space.set_resolution(1e-6);  // 2e6 segments: over the cached-order size, through the generator
  StraightLinePlanner lp(w.space, *w.checker);
  ASSERT_TRUE(lp.connect(state2(1, 1), state2(3, 1)));
  EXPECT_EQ(w.counters.cd_calls(), static_cast<std::uint64_t>(core::edge_segments(2.0, 1e-6) - 1));
}

// A grid A* around a wall with no gap explores the whole left half; at a fine resolution every move
// it finds would be checked in millions of steps. Either way the stop ends the search.
TEST(LongEdge, GridAStarStopsAtTheTimeLimit) {
  WallWorld w;
  w.space.set_resolution(1e-9);  // each grid move (10 / 128) takes 7.8e7 steps to check
  const core::StopCondition stop(0.05, kNoNodeLimit);
  GridAStarSettings s;
  s.max_cells = 1000000000;  // the largest accepted: no cap within these tests
  GridAStarPlanner astar(w.space, *w.checker, s, &stop);
  EXPECT_FALSE(astar.connect(state2(1, 1), state2(3, 2)));
  EXPECT_TRUE(astar.last().stopped);
  EXPECT_TRUE(astar.last().abandoned);
  EXPECT_EQ(stop.check(0), core::StopReason::kTimeLimit);
  EXPECT_FALSE(astar.connect(state2(1, 1), state2(1.1, 1)));  // refused at once from now on
  EXPECT_EQ(astar.last().cells_checked, 0u);
}

TEST(LongEdge, GridAStarSearchOfManyCellsStopsAtTheTimeLimit) {
  WallWorld w;  // closed wall: the search exhausts the left half (about 57 x 128 cells) ...
  const core::StopCondition stop(0.0, kNoNodeLimit);  // ... unless stopped first
  GridAStarSettings s;
  s.steps = 4096;  // ~10^7 cells on the left: without the stop, seconds of search
  s.max_cells = 1000000000;  // the largest accepted: no cap within these tests
  GridAStarPlanner astar(w.space, *w.checker, s, &stop);
  EXPECT_FALSE(astar.connect(state2(1, 1), state2(9, 9)));
  EXPECT_TRUE(astar.last().stopped);
  EXPECT_LE(astar.last().cells_checked, core::StopPoll::kStride);
}

TEST(LongEdge, GridAStarWithoutStopSearchesToExhaustion) {
  WallWorld w;
  GridAStarSettings s;
  s.max_cells = 1000000000;  // the largest accepted: no cap within these tests
  GridAStarPlanner astar(w.space, *w.checker, s);
  EXPECT_FALSE(astar.connect(state2(1, 1), state2(9, 9)));
  EXPECT_FALSE(astar.last().stopped);
  EXPECT_FALSE(astar.last().abandoned);
}

}  // namespace
}  // namespace amp::roadmap
