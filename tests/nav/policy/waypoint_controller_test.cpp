#include "amp/nav/policy/waypoint_controller.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/unicycle_space.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/simulator.hpp"
#include "amp/nav/unicycle_disc.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

State waypoint(double x, double y, double v) { return core::UnicycleSpace::make_state(x, y, 0.0, v, 0.0); }

RobotState at(double x, double y, double heading) {
  RobotState s;
  s.position = V(x, y);
  s.heading = heading;
  return s;
}

TEST(WaypointController, SteersTowardTheWaypointByHand) {
  WaypointController c({waypoint(1, 0, 0.2), waypoint(1, 1, 0.2)});
  // Facing the first waypoint (1 m ahead): full speed, no turn.
  const V ahead = c.command(at(0, 0, 0.0));
  EXPECT_DOUBLE_EQ(ahead.x(), 0.2);
  EXPECT_DOUBLE_EQ(ahead.y(), 0.0);
  // Heading pi/3 off: v = 0.2 cos(pi/3) = 0.1, omega = 2.5 * (-pi/3).
  const V off = c.command(at(0, 0, kPi / 3));
  EXPECT_NEAR(off.x(), 0.1, 1e-12);
  EXPECT_NEAR(off.y(), -2.5 * kPi / 3, 1e-12);
  // Behind: turn on the spot.
  EXPECT_DOUBLE_EQ(c.command(at(2, 0, 0.0)).x(), 0.0);
  EXPECT_EQ(c.current(), 0u);
}

TEST(WaypointController, SwitchesWithinDApproachAndStopsAtTheGoal) {
  WaypointController c({waypoint(1, 0, 0.2), waypoint(1, 1, 0.2)});
  // 0.25 m from the first waypoint (d_approach 0.3): on to the second, which is the last. The robot
  // projects onto the segment's start (t = 0), so it aims d_approach along the segment, at (1, 0.3):
  // bearing atan2(0.3, 0.25) from (0.75, 0). The brake cap sqrt(2 * 2.5 * 1.03) is far above 0.2.
  const V cmd = c.command(at(0.75, 0.0, 0.0));
  EXPECT_EQ(c.current(), 1u);
  const double e = std::atan2(0.3, 0.25);
  EXPECT_NEAR(cmd.x(), 0.2 * std::cos(e), 1e-12);
  EXPECT_NEAR(cmd.y(), 2.5 * e, 1e-12);
  // 0.2 m from the goal: v <= sqrt(2 * 2.5 * 0.2) = 1, so the waypoint's 0.2 rules; braking at
  // 0.05 m/s^2 the cap sqrt(2 * 0.05 * 0.2) = 0.141 does. Within 0.1: stop.
  EXPECT_NEAR(c.command(at(1.0, 0.8, kPi / 2)).x(), 0.2, 1e-12);
  WaypointControllerSettings gentle;
  gentle.accel = 0.05;
  WaypointController slow({waypoint(1, 1, 0.2)}, gentle);
  EXPECT_NEAR(slow.command(at(1.0, 0.8, kPi / 2)).x(), std::sqrt(0.02), 1e-12);
  EXPECT_EQ(c.command(at(1.0, 0.95, kPi / 2)), V::Zero());
  EXPECT_TRUE(c.arrived(at(1.0, 0.95, kPi / 2)));
  EXPECT_FALSE(c.arrived(at(1.0, 0.8, kPi / 2)));
}

TEST(WaypointController, DrivesAUnicycleRoundACornerInTheSimulator) {
  // A 4 m square room with a 2 m wall from the bottom at x = 2: the policy goes up and over it.
  world::Shapes2d s;
  s.polygons.push_back({{{1.9, 0.0}, {2.1, 0.0}, {2.1, 2.0}, {1.9, 2.0}}});
  const auto world = std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), V(4, 4)));
  const auto timeline = std::make_shared<const WorldTimeline>(world, std::vector<WorldEvent>{});
  const auto robot = std::make_shared<const UnicycleDisc>();
  Simulator sim(timeline, robot, at(1.0, 1.0, 0.0));
  WaypointController c({waypoint(1.0, 1.0, 0.26), waypoint(1.0, 3.0, 0.26), waypoint(3.0, 3.0, 0.26),
                        waypoint(3.0, 1.0, 0.26)});
  core::Rng rng(1);
  std::size_t steps = 0;
  double nearest = 1e9;
  while (!c.arrived(sim.state()) && steps < 2000) {
    sim.step(c.command(sim.state()), rng);
    nearest = std::min(nearest, sim.next_world().clearance(sim.state().position, robot->radius()));
    ++steps;
  }
  EXPECT_TRUE(c.arrived(sim.state()));
  EXPECT_EQ(sim.blocked_moves(), 0u);
  EXPECT_GT(nearest, 0.0);
  // About 6 m at 0.26 m/s (with the corners cut by d_approach and turns on the spot): 20-40 s.
  EXPECT_GT(steps, 200u);
  EXPECT_LT(steps, 400u);
}

TEST(WaypointController, DrivesTheSpeedThePolicyValueAssumedAlongTheSegment) {
  // PolicyValue interpolates the speed between the waypoints; so does the controller. Past the
  // first waypoint (within d_approach of it), at 10% of the segment: 0.1 + 0.1 (0.2 - 0.1) = 0.11;
  // at 60% (still 0.4 m from the second waypoint): 0.16.
  WaypointController c({waypoint(0, 0, 0.1), waypoint(1, 0, 0.2), waypoint(2, 0, 0.2)});
  EXPECT_NEAR(c.command(at(0.1, 0, 0.0)).x(), 0.11, 1e-12);
  EXPECT_EQ(c.current(), 1u);
  EXPECT_NEAR(c.command(at(0.6, 0, 0.0)).x(), 0.16, 1e-12);
}

TEST(WaypointController, RetreatsToThePassedWaypointAfterAContact) {
  // A wall across the way at x = 1.0: the robot (radius 0.27) drives into it, the simulator refuses
  // the move, and the controller goes back to the waypoint it passed (0.3, 1) before trying again.
  world::Shapes2d s;
  s.polygons.push_back({{{1.0, 0.0}, {1.1, 0.0}, {1.1, 2.0}, {1.0, 2.0}}});
  const auto world = std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), V(2, 2)));
  const auto timeline = std::make_shared<const WorldTimeline>(world, std::vector<WorldEvent>{});
  const auto robot = std::make_shared<const UnicycleDisc>();
  Simulator sim(timeline, robot, at(0.3, 1.0, 0.0));
  WaypointController c({waypoint(0.3, 1.0, 0.2), waypoint(1.6, 1.0, 0.2)});
  core::Rng rng(1);
  std::size_t steps = 0;
  while (!c.retreating() && steps < 200) {
    sim.step(c.command(sim), rng);
    ++steps;
  }
  ASSERT_TRUE(c.retreating());
  EXPECT_GE(sim.blocked_moves(), 1u);
  EXPECT_LE(sim.state().position.x(), 1.0 - 0.27 + 1e-9);  // never into the wall
  while (c.retreating() && steps < 600) {
    sim.step(c.command(sim), rng);
    ++steps;
  }
  EXPECT_FALSE(c.retreating());
  EXPECT_LT((sim.state().position - V(0.3, 1.0)).norm(), 0.1);  // back where the segment begins
  EXPECT_EQ(c.current(), 1u);  // and on toward the next waypoint again
}

TEST(WaypointController, TurnsOnTheSpotWhereAFootprintWasCertifiedToByHand) {
  // As a rectangle is driven: switch within 3 cm (or once past), aim 0.3 m ahead, turn in place
  // above 0.2 rad of heading error; braking at 0.05 m/s^2, so that the cap sqrt(2 a d) shows.
  WaypointControllerSettings s;
  s.d_approach = 0.03;
  s.lookahead = 0.3;
  s.turn_in_place = 0.2;
  s.accel = 0.05;
  WaypointController c({waypoint(0, 0, 0.2), waypoint(1, 0, 0.2), waypoint(1, 1, 0.2), waypoint(1.1, 2, 0.2)}, s);
  // From the start toward the right-angle turn at (1, 0), braking to stop there: at 1 m the cap
  // sqrt(0.1) is above 0.2; at 0.1 m it is sqrt(0.1 * 0.1) = 0.1.
  EXPECT_NEAR(c.command(at(0.0, 0.0, 0.0)).x(), 0.2, 1e-12);
  EXPECT_EQ(c.current(), 1u);
  EXPECT_NEAR(c.command(at(0.9, 0.0, 0.0)).x(), 0.1, 1e-12);
  // 4 cm beside it and 1 mm past its line: reached, though not within d_approach. The aim is 0.3 m
  // up the next segment from the projection (t = 0.04), at (1, 0.34): e = atan2(0.3, -0.001) is far
  // above 0.2 rad, so v = 0 and the robot turns on the spot.
  const V turn = c.command(at(1.001, 0.04, 0.0));
  EXPECT_EQ(c.current(), 2u);
  EXPECT_EQ(turn.x(), 0.0);
  EXPECT_NEAR(turn.y(), 2.5 * std::atan2(0.3, -0.001), 1e-12);
  // Lined up within 0.2 rad it drives again: from (1, 0.1) facing 1.5 rad, e = pi/2 - 1.5.
  EXPECT_NEAR(c.command(at(1.0, 0.1, 1.5)).x(), 0.2 * std::cos(kPi / 2 - 1.5), 1e-12);
  // The turn of atan(0.1) < 0.2 rad at (1, 1) is not stopped at: no brake before it, and passing
  // it 5 cm aside does not reach it.
  EXPECT_NEAR(c.command(at(1.0, 0.9, kPi / 2)).x(), 0.2, 1e-12);
  c.command(at(1.05, 1.001, kPi / 2));
  EXPECT_EQ(c.current(), 2u);
  // The paper's controller (turn_in_place infinite) drives at v cos e short of 90 degrees.
  WaypointController paper({waypoint(0, 0, 0.2), waypoint(1, 0, 0.2), waypoint(1, 1, 0.2)});
  EXPECT_NEAR(paper.command(at(0.0, 0.0, 0.5)).x(), 0.2 * std::cos(0.5), 1e-12);
}

TEST(WaypointController, RefusesBadSettings) {
  WaypointControllerSettings bad;
  bad.d_approach = 0.0;
  EXPECT_THROW(WaypointController({waypoint(0, 0, 1)}, bad), ParameterError);
  WaypointControllerSettings no_turn;
  no_turn.turn_in_place = 0.0;
  EXPECT_THROW(WaypointController({waypoint(0, 0, 1)}, no_turn), ParameterError);
  WaypointControllerSettings behind;
  behind.lookahead = -1.0;
  EXPECT_THROW(WaypointController({waypoint(0, 0, 1)}, behind), ParameterError);
  EXPECT_THROW(WaypointController({}), ParameterError);
}

}  // namespace
}  // namespace amp::nav
