#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "amp/core/rng.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/polygon_geometry.hpp"
#include "support/state_of.hpp"

namespace amp::world {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

using test::st;

Polygon rect(double x0, double y0, double x1, double y1) { return Polygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}; }

// Environment + checker + counters bundled for the hand-made cases.
struct Fixture {
  Fixture(Shapes2d obstacles, PlanarRobot robot, Eigen::AlignedBox2d bounds = {V(0, 0), V(10, 10)})
      : env(std::make_shared<const PlanarWorld>(std::move(obstacles), bounds), std::move(robot)),
        checker(env.make_checker(counters)) {}
  bool valid(const State& s) const { return checker->is_valid(s); }
  core::Counters counters;
  PlanarEnvironment env;
  std::unique_ptr<ValidityChecker> checker;
};

PlanarRobot square_robot(double side) {
  const double h = side / 2;
  return PlanarRobot::rigid({{rect(-h, -h, h, h)}, {}});
}

TEST(PlanarChecker, TouchingCountsAsCollision) {
  Fixture f({{rect(4, 4, 6, 6)}, {}}, square_robot(1.0));
  EXPECT_TRUE(f.valid(st({2, 5, 0})));
  EXPECT_FALSE(f.valid(st({3.5, 5, 0})));         // robot x in [3, 4]: shares the edge x = 4
  EXPECT_TRUE(f.valid(st({3.5 - 1e-9, 5, 0})));
  EXPECT_FALSE(f.valid(st({3.5, 3.5, 0})));       // corner to corner
  EXPECT_FALSE(f.valid(st({5, 5, 0.3})));
}

TEST(PlanarChecker, ContainmentBothWays) {
  Fixture robot_inside({{rect(2, 2, 8, 8)}, {}}, square_robot(1.0));
  EXPECT_FALSE(robot_inside.valid(st({5, 5, 0.7})));
  Fixture obstacle_inside({{rect(4.8, 4.8, 5.2, 5.2)}, {Circle{{7, 7}, 0.1}}}, square_robot(3.0));
  EXPECT_FALSE(obstacle_inside.valid(st({5, 5, 0.2})));
  EXPECT_FALSE(obstacle_inside.valid(st({7.2, 7.0, 0.0})));  // the small circle inside the robot
  Fixture disc_inside({{rect(2, 2, 8, 8)}, {Circle{{1, 9}, 0.8}}},
                      PlanarRobot::translating({{}, {Circle{{0, 0}, 0.3}}}));
  EXPECT_FALSE(disc_inside.valid(st({5, 5})));
  EXPECT_FALSE(disc_inside.valid(st({1.1, 8.9})));  // inside the circle obstacle
  EXPECT_TRUE(disc_inside.valid(st({9, 1})));
}

TEST(PlanarChecker, RotatedRobot) {
  // A 2 x 0.2 bar: lying along x it reaches the obstacle, standing up it does not.
  Fixture f({{rect(4, 4, 6, 6)}, {}}, PlanarRobot::rigid({{rect(-1, -0.1, 1, 0.1)}, {}}));
  EXPECT_FALSE(f.valid(st({3.2, 5, 0})));
  EXPECT_TRUE(f.valid(st({3.2, 5, kPi / 2})));
  // At 45 degrees the bar's far corner reaches x = 3.2 + (1 + 0.1) / sqrt(2) = 3.978: clear.
  EXPECT_TRUE(f.valid(st({3.2, 5, kPi / 4})));
  EXPECT_FALSE(f.valid(st({3.3, 5, kPi / 4})));  // 4.078
}

TEST(PlanarChecker, WrappedAnglesGiveTheSameAnswer) {
  Fixture f({{rect(4, 4, 6, 6), rect(1, 7, 3, 8)}, {Circle{{7, 2}, 1}}},
            PlanarRobot::rigid({{rect(-1, -0.1, 1, 0.1), rect(-1, -0.1, -0.8, 0.8)}, {}}));
  core::Rng rng(7);
  int differing = 0, invalid = 0;
  for (int i = 0; i < 2000; ++i) {
    const double x = rng.uniform(0, 10), y = rng.uniform(0, 10), t = rng.uniform(-kPi, kPi);
    const bool a = f.valid(st({x, y, t}));
    differing += a != f.valid(st({x, y, t + 2 * kPi})) || a != f.valid(st({x, y, t - 4 * kPi}));
    invalid += !a;
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(invalid, 100);  // the sample really exercised collisions
}

TEST(PlanarChecker, RobotInsideTheNotchOfAUShapedObstacle) {
  const Polygon u{{{3, 3}, {6, 3}, {6, 6}, {5, 6}, {5, 4}, {4, 4}, {4, 6}, {3, 6}}};
  Fixture f({{u}, {}}, square_robot(0.5));
  EXPECT_TRUE(f.valid(st({4.5, 5, 0})));         // in the notch, 0.25 from each wall
  EXPECT_TRUE(f.valid(st({4.5, 5, kPi / 4})));    // rotated: half-diagonal 0.354 < 0.5
  EXPECT_FALSE(f.valid(st({4.3, 5, kPi / 4})));   // 4.3 - 0.354 < 4: hits the left wall
  EXPECT_FALSE(f.valid(st({4.5, 4.2, 0})));       // sits on the floor of the notch
  EXPECT_FALSE(f.valid(st({3.5, 5, 0})));         // inside the left arm
  EXPECT_FALSE(f.valid(st({5.5, 3.5, 0})));       // inside the base
  EXPECT_TRUE(f.valid(st({4.5, 6.5, 0})));        // above the notch
}

TEST(PlanarChecker, WorkspaceBounds) {
  Fixture f({}, square_robot(1.0));
  EXPECT_TRUE(f.valid(st({0.5, 0.5, 0})));   // touches the walls: still inside the closed box
  EXPECT_FALSE(f.valid(st({0.2, 5, 0})));
  EXPECT_FALSE(f.valid(st({5, 9.8, 0.1})));
  EXPECT_FALSE(f.valid(st({5, NAN, 0})));
}

TEST(PlanarChecker, DiscsAndPointsAgainstCircles) {
  Fixture disc({{rect(4, 4, 6, 6)}, {Circle{{5, 8}, 1}}}, PlanarRobot::translating({{}, {Circle{{0, 0}, 0.5}}}));
  EXPECT_FALSE(disc.valid(st({6.5, 8})));  // tangent
  EXPECT_TRUE(disc.valid(st({6.5 + 1e-9, 8})));
  EXPECT_FALSE(disc.valid(st({6.5, 5})));  // tangent to the square's edge
  EXPECT_FALSE(disc.valid(st({6.3, 6.3})));  // 0.424 from the corner
  EXPECT_TRUE(disc.valid(st({6.4, 6.4})));   // 0.566 from the corner
  Fixture point({{rect(4, 4, 6, 6)}, {Circle{{5, 8}, 1}}}, PlanarRobot::translating({{}, {Circle{{0, 0}, 0.0}}}));
  EXPECT_FALSE(point.valid(st({6, 5})));    // on the edge
  EXPECT_FALSE(point.valid(st({5, 5})));    // inside
  EXPECT_FALSE(point.valid(st({5, 7})));    // on the circle
  EXPECT_TRUE(point.valid(st({6.01, 5})));
  EXPECT_TRUE(point.valid(st({0, 0})));     // on the bounds corner: inside the closed box
}

TEST(PlanarChecker, EveryCheckIsOneCdCall) {
  Fixture f({{rect(4, 4, 6, 6)}, {}}, square_robot(1.0));
  f.counters.set_phase(core::Phase::kTraining);
  for (int i = 0; i < 7; ++i) f.valid(st({1.0 + i, 5, 0}));
  EXPECT_EQ(f.counters.cd_calls(), 7u);
  EXPECT_EQ(f.counters.cd_calls(core::Phase::kTraining), 7u);
  const Clearance c = f.checker->clearance(st({2, 5, 0}));
  EXPECT_EQ(f.counters.cd_calls(), 7u);  // a clearance query is not a CD call
  EXPECT_EQ(f.counters.clearance_calls(), 1u);
  EXPECT_NEAR(c.distance, 1.5, 1e-12);
  EXPECT_NEAR(c.robot_point.x(), 2.5, 1e-12);
  EXPECT_NEAR(c.obstacle_point.x(), 4.0, 1e-12);
  EXPECT_EQ(f.checker->clearance(st({5, 5, 0})).distance, 0.0);
}

TEST(PlanarChecker, ClearanceIgnoresBoundsAndHandlesCircles) {
  Fixture f({{}, {Circle{{5, 5}, 1}}}, PlanarRobot::translating({{}, {Circle{{0, 0}, 0.5}}}));
  const Clearance c = f.checker->clearance(st({8, 9}));  // 1 from the top wall, 3.5 from the circle
  EXPECT_NEAR(c.distance, 3.5, 1e-12);
  EXPECT_NEAR((c.robot_point - c.obstacle_point).norm(), 3.5, 1e-12);
  EXPECT_NEAR((c.obstacle_point - Eigen::Vector3d(5, 5, 0)).norm(), 1.0, 1e-12);
  Fixture empty({}, square_robot(1.0));
  EXPECT_EQ(empty.checker->clearance(st({5, 5, 0})).distance, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace amp::world
