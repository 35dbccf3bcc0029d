#include "amp/nav/execution.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"
#include "amp/core/unicycle_space.hpp"
#include "amp/nav/policy/policy_planner.hpp"
#include "amp/nav/policy/waypoint_controller.hpp"
#include "amp/nav/simulator.hpp"
#include "amp/nav/unicycle_disc.hpp"
#include "nav/lab_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

// The searched policy of the lab driven on the noisy unicycle: it arrives where it says, never
// through a wall, and one seed gives one run.
Execution drive(const std::vector<State>& policy, std::uint64_t seed, const MotionNoise& noise) {
  const auto world = test::lab();
  RobotState s;
  s.position = V(1.0, 1.0);
  Simulator sim(std::make_shared<const WorldTimeline>(world, std::vector<WorldEvent>{}),
                std::make_shared<const UnicycleDisc>(), s);
  WaypointController controller(policy);
  core::Rng rng(seed);
  return execute(sim, controller, noise, 300.0, rng);
}

TEST(Execution, ThePolicyLeavesTheLabOnTheNoisyRobot) {
  const auto world = test::lab();
  const PolicyPlan plan = plan_policy(*world, V(1.0, 1.0), V(3.5, 4.3), 0.27);
  MotionNoise noise;
  noise.sigma_v = 0.1;
  noise.sigma_omega = 0.1;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Execution e = drive(plan.search.final, seed, noise);
    EXPECT_TRUE(e.arrived) << seed;
    EXPECT_LT((e.trace.back() - V(3.5, 4.3)).norm(), 0.1) << seed;
    EXPECT_GE(e.min_clearance, 0.0) << seed;  // the simulator never lets the disc overlap a wall
    EXPECT_GT(e.distance, 4.0);
    EXPECT_EQ(e.speeds.size() + 1, e.trace.size());
  }
  const Execution a = drive(plan.search.final, 7, noise), b = drive(plan.search.final, 7, noise);
  EXPECT_EQ(a.trace, b.trace);
  const Execution c = drive(plan.search.final, 8, noise);
  EXPECT_NE(a.trace, c.trace);
}

TEST(Execution, StopsAtItsTimeLimit) {
  const auto world = test::lab(false);  // the door is shut: the goal cannot be reached
  RobotState s;
  s.position = V(1.0, 1.0);
  Simulator sim(std::make_shared<const WorldTimeline>(world, std::vector<WorldEvent>{}),
                std::make_shared<const UnicycleDisc>(), s);
  WaypointController controller({core::UnicycleSpace::make_state(3.5, 4.3, 0, 0.26, 0)});
  core::Rng rng(1);
  const Execution e = execute(sim, controller, MotionNoise{}, 20.0, rng);
  EXPECT_FALSE(e.arrived);
  EXPECT_NEAR(e.time_s, 20.0, 0.1 + 1e-9);
  EXPECT_GT(e.collisions, 0u);  // it drove into the wall, and was stopped there
  EXPECT_GE(e.min_clearance, 0.0);
}

}  // namespace
}  // namespace amp::nav
