// A validity check (and a clearance query) must not touch the heap: global operator new is
// replaced by a counting one for this executable.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"

#include <memory>
#include <numbers>

#include "amp/core/rng.hpp"
#include "amp/world/planar_checker.hpp"

using amp::test::g_allocations;

namespace amp::world {
namespace {

using V = Eigen::Vector2d;

TEST(PlanarAllocation, ChecksAndClearanceDoNotAllocate) {
  Shapes2d obstacles;
  core::Rng rng(5);
  for (int i = 0; i < 200; ++i) {
    const V c(rng.uniform(0, 30), rng.uniform(0, 30));
    const double r = rng.uniform(0.2, 1.0);
    obstacles.polygons.push_back(Polygon{{c, c + V(r, 0), c + V(r, r), c + V(0.5 * r, 0.3 * r), c + V(0, r)}});
  }
  for (int i = 0; i < 30; ++i) obstacles.circles.push_back({{rng.uniform(0, 30), rng.uniform(0, 30)}, 0.5});
  const auto world = std::make_shared<const PlanarWorld>(obstacles, Eigen::AlignedBox2d(V(0, 0), V(30, 30)));
  const Polygon bar{{{-1, -0.15}, {1, -0.15}, {1, 0.15}, {-1, 0.15}}};
  const PlanarRobot robots[] = {PlanarRobot::rigid({{bar}, {Circle{{1, 1}, 0.3}}}),
                                PlanarRobot::fixed_arm({15, 15, 0}, {{3, 0.2}, {2, 0.2}, {2, 0.2}})};
  for (const PlanarRobot& robot : robots) {
    core::Counters counters;
    PlanarChecker checker(world, robot, counters);
    std::vector<State> states(500, State(robot.state_dimension()));
    for (State& s : states) {
      for (int i = 0; i < s.size(); ++i) s[i] = i < 2 && robot.state_dimension() == 3 ? rng.uniform(0, 30) : rng.uniform(-3.2, 3.2);
    }
    int valid = 0;
    const long before = g_allocations.load();
    for (const State& s : states) valid += checker.is_valid(s);
    for (const State& s : states) checker.clearance(s);
    EXPECT_EQ(g_allocations.load() - before, 0);
    EXPECT_GT(valid, 0);
    EXPECT_LT(valid, 500);
  }
}

}  // namespace
}  // namespace amp::world
