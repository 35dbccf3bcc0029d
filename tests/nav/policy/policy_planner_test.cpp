#include "amp/nav/policy/policy_planner.hpp"

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/footprint.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/policy/footprint_drive.hpp"
#include "amp/nav/policy/policy_search.hpp"
#include "amp/nav/policy/policy_value.hpp"
#include "nav/lab_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

using test::lab;

TEST(PolicyPlanner, OutOfTheLabThroughTheDoor) {
  const auto world = lab();
  const V start(1.0, 1.0), goal(3.5, 4.3);
  const PolicyPlan plan = plan_policy(*world, start, goal, 0.27);
  const PolicySearchResult& r = plan.search;
  ASSERT_GE(r.final.size(), 2u);
  // The phases never lose value, and the start and goal stay put.
  EXPECT_GE(r.value_searched, r.value_projected);
  EXPECT_GE(r.value_final, r.value_searched);
  EXPECT_GT(r.value_final, r.value_projected);  // the projected zigzag is improved on
  for (const auto* w : {&r.projected, &r.searched, &r.final}) {
    EXPECT_DOUBLE_EQ((*w).front()[0], start.x());
    EXPECT_DOUBLE_EQ((*w).front()[1], start.y());
    EXPECT_DOUBLE_EQ((*w).back()[0], goal.x());
    EXPECT_DOUBLE_EQ((*w).back()[1], goal.y());
  }
  // Every segment of the final policy is free for the 54 cm disc, and it passes the door.
  bool through_door = false;
  for (std::size_t j = 1; j < r.final.size(); ++j) {
    const V a(r.final[j - 1][0], r.final[j - 1][1]), b(r.final[j][0], r.final[j][1]);
    EXPECT_TRUE(segment_free(*world, a, b, 0.27)) << "segment " << j;
    if ((a.y() - 3.55) * (b.y() - 3.55) < 0.0) {
      const double x = a.x() + (3.55 - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
      through_door = x > 1.7 + 0.27 && x < 2.3 - 0.27;
    }
  }
  EXPECT_TRUE(through_door);
  // Fewer waypoints than the value function's cells, and deterministic.
  EXPECT_LT(r.final.size(), plan.dp_path.size());
  const PolicyPlan again = plan_policy(*world, start, goal, 0.27);
  ASSERT_EQ(again.search.final.size(), r.final.size());
  for (std::size_t j = 0; j < r.final.size(); ++j) EXPECT_EQ(again.search.final[j], r.final[j]);
}

TEST(PolicyPlanner, ARectangleLinesUpWithTheDoorAtItsHeading) {
  // 0.7 m x 0.54 m: it cannot turn in the door, so the plan drives through it straight, every
  // segment and every turn in place certified for the whole footprint; one request, one plan.
  const auto world = lab();
  const Footprint f = Footprint::rectangle(0.7, 0.54);
  // (The disc's goal, 0.5 m from the east wall, cannot be reached facing east by a 0.7 m body.)
  const V start(1.0, 1.0), goal(3.0, 4.3);
  const PolicyPlan plan = plan_policy(*world, start, goal, f);
  const PolicySearchResult& r = plan.search;
  ASSERT_GE(r.final.size(), 2u);
  const PolicyValue value(*world, f);
  for (const auto* w : {&r.projected, &r.searched, &r.final}) {
    EXPECT_TRUE(policy_free(value, *w));
    EXPECT_EQ(V(w->front()[0], w->front()[1]), start);
    EXPECT_EQ(V(w->back()[0], w->back()[1]), goal);
  }
  EXPECT_GE(r.value_final, r.value_projected);
  const PolicyPlan again = plan_policy(*world, start, goal, f);
  EXPECT_EQ(again.search.final, r.final);
  // The disc's own plan is free for the disc, not for the rectangle, which would turn in the door.
  const PolicyPlan disc = plan_policy(*world, start, goal, 0.27);
  EXPECT_TRUE(policy_free(PolicyValue(*world, 0.27), disc.search.final));
  EXPECT_FALSE(policy_free(value, disc.search.projected));
  // A rectangle too long to turn out of the corridor above the door (1.4 m deep) gets a clear error.
  EXPECT_THROW(plan_policy(*world, start, goal, Footprint::rectangle(3.0, 0.54)), ParameterError);
}

TEST(PolicyPlanner, BadRequestsGetOneLineErrors) {
  const auto world = lab();
  auto message = [&](const std::shared_ptr<const GridNavWorld>& w, V s, V g, double r) {
    try {
      plan_policy(*w, s, g, r);
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(world, V(1, 1), V(3.5, 4.3), 0.35).find("no passage wide enough for the footprint"), std::string::npos);
  EXPECT_NE(message(lab(false), V(1, 1), V(3.5, 4.3), 0.27).find("not reachable"), std::string::npos);
  EXPECT_NE(message(world, V(1, 3.55), V(3.5, 4.3), 0.27).find("start"), std::string::npos);
  EXPECT_NE(message(world, V(1, 1), V(3.9, 4.3), 0.27).find("goal"), std::string::npos);
}

// A run's time limit reaches into planning: value iteration over the lab's 8,000 cells reads the
// stop every 4,096 cells, and the search before each waypoint's step.
TEST(PolicyPlanner, AnExpiredStopEndsValueIterationAndTheSearch) {
  const auto world = lab();
  const V start(1.0, 1.0), goal(3.5, 4.3);
  const core::StopCondition expired(0.0, 1000);
  const PolicyPlan cut = plan_policy(*world, start, goal, 0.27, {}, &expired);
  EXPECT_TRUE(cut.stopped);
  EXPECT_TRUE(cut.dp_path.empty());
  EXPECT_TRUE(cut.search.final.empty());

  // The search stopped before its first step keeps the projected policy as it is.
  const PolicyPlan full = plan_policy(*world, start, goal, 0.27);
  EXPECT_FALSE(full.stopped);
  const PolicyValue value(*world, Footprint::disc(0.27), PolicyRewardSettings{});
  const PolicySearchResult r = search_policy(full.search.projected, value, {}, &expired);
  EXPECT_TRUE(r.stopped);
  EXPECT_EQ(r.insertions, 0);
  ASSERT_EQ(r.final.size(), full.search.projected.size());
  for (std::size_t j = 0; j < r.final.size(); ++j) EXPECT_EQ(r.final[j], full.search.projected[j]) << j;
  EXPECT_DOUBLE_EQ(r.value_final, r.value_projected);
}

}  // namespace
}  // namespace amp::nav
