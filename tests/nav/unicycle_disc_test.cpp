#include "amp/nav/unicycle_disc.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::nav {
namespace {

RobotState moving(double x, double y, double heading, double v, double omega) {
  RobotState s;
  s.position = Eigen::Vector2d(x, y);
  s.heading = heading;
  s.velocity = Eigen::Vector2d(v, omega);
  return s;
}

TEST(UnicycleDisc, HeldVelocitiesGiveLinesAndArcs) {
  const UnicycleDisc robot;
  // 0.2 m/s along heading 0.5 for 1 s.
  const RobotState a = robot.propagate(moving(1, 2, 0.5, 0.2, 0.0), {0.2, 0.0}, 1.0);
  EXPECT_NEAR(a.position.x(), 1.0 + 0.2 * std::cos(0.5), 1e-12);
  EXPECT_NEAR(a.position.y(), 2.0 + 0.2 * std::sin(0.5), 1e-12);
  EXPECT_NEAR(a.heading, 0.5, 1e-12);
  // v = 0.2, omega = 0.5 for 2 s: an arc of radius 0.4 turning by 1 rad from heading 0:
  // (0.4 sin 1, 0.4 (1 - cos 1)).
  const RobotState b = robot.propagate(moving(0, 0, 0.0, 0.2, 0.5), {0.2, 0.5}, 2.0);
  EXPECT_NEAR(b.position.x(), 0.4 * std::sin(1.0), 1e-12);
  EXPECT_NEAR(b.position.y(), 0.4 * (1.0 - std::cos(1.0)), 1e-12);
  EXPECT_NEAR(b.heading, 1.0, 1e-12);
}

TEST(UnicycleDisc, AccelerationRampsByHand) {
  const UnicycleDisc robot;  // accel 2.5 m/s^2, v_max 0.26: the ramp from rest lasts 0.104 s
  const RobotState mid = robot.propagate(moving(0, 0, 0, 0, 0), {1.0, 0.0}, 0.05);
  EXPECT_NEAR(mid.position.x(), 0.5 * 2.5 * 0.05 * 0.05, 1e-12);
  EXPECT_NEAR(mid.velocity.x(), 0.125, 1e-12);
  const RobotState after = robot.propagate(moving(0, 0, 0, 0, 0), {1.0, 0.0}, 0.2);
  EXPECT_NEAR(after.position.x(), 0.5 * 2.5 * 0.104 * 0.104 + 0.26 * (0.2 - 0.104), 1e-12);
  EXPECT_NEAR(after.velocity.x(), 0.26, 1e-12);
  // Turning on the spot: heading alpha t^2 / 2 while omega ramps (alpha 3.2, t 0.1 < 1 / 3.2).
  const RobotState turn = robot.propagate(moving(3, 4, 0.2, 0, 0), {0.0, 1.0}, 0.1);
  EXPECT_NEAR(turn.heading, 0.2 + 0.5 * 3.2 * 0.01, 1e-12);
  EXPECT_TRUE(turn.position.isApprox(Eigen::Vector2d(3, 4)));
}

TEST(UnicycleDisc, BothRampsMatchAFineIntegration) {
  const UnicycleDisc robot;
  const RobotState s = moving(0.5, -0.5, 2.0, 0.05, -0.4);
  const Eigen::Vector2d command(0.26, 0.9);
  const double t = 0.7;
  // Reference: explicit midpoint steps of 1 microsecond with the same velocity ramps.
  const int n = 700000;
  const double h = t / n;
  double x = 0.5, y = -0.5, th = 2.0, v = 0.05, w = -0.4;
  for (int i = 0; i < n; ++i) {
    const double v1 = std::min(0.26, v + 2.5 * h), w1 = std::min(0.9, w + 3.2 * h);
    const double vm = 0.5 * (v + v1), thm = th + 0.5 * h * 0.5 * (w + w1);
    x += h * vm * std::cos(thm);
    y += h * vm * std::sin(thm);
    th += h * 0.5 * (w + w1);
    v = v1, w = w1;
  }
  const RobotState out = robot.propagate(s, command, t);
  EXPECT_NEAR(out.position.x(), x, 1e-9);
  EXPECT_NEAR(out.position.y(), y, 1e-9);
  EXPECT_NEAR(out.heading, std::remainder(th, 2.0 * std::numbers::pi), 1e-9);
  EXPECT_NEAR(out.velocity.x(), 0.26, 1e-12);
  EXPECT_NEAR(out.velocity.y(), 0.9, 1e-12);
}

TEST(UnicycleDisc, ClipsCommandsAndBoundsSpeed) {
  const UnicycleDisc robot;
  EXPECT_TRUE(robot.clipped({5.0, -7.0}).isApprox(Eigen::Vector2d(0.26, -1.0)));
  EXPECT_TRUE(robot.clipped({-1.0, 0.5}).isApprox(Eigen::Vector2d(0.0, 0.5)));  // no reversing
  EXPECT_EQ(robot.clipped({NAN, 0.0}), Eigen::Vector2d::Zero());
  EXPECT_DOUBLE_EQ(robot.speed_bound(moving(0, 0, 0, 0.1, 0), {1.0, 0.0}), 0.26);
  EXPECT_DOUBLE_EQ(robot.speed_bound(moving(0, 0, 0, 0.2, 0), {0.0, 0.0}), 0.2);
  UnicycleDiscSettings bad;
  bad.accel = 0.0;
  EXPECT_THROW(UnicycleDisc{bad}, ParameterError);
  bad = {};
  bad.v_min = 0.1;
  EXPECT_THROW(UnicycleDisc{bad}, ParameterError);
}

}  // namespace
}  // namespace amp::nav
