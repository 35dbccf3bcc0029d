#include "amp/nav/straight_leg.hpp"

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"
#include "amp/nav/holonomic_disc.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

// A 2 m x 1 m room with a wall across x = 1 from y = 0 to y = 0.7 (a gap above it).
Simulator make_sim(V start, double noise = 0.0) {
  world::Shapes2d s;
  s.polygons.push_back({{{0.98, 0.0}, {1.02, 0.0}, {1.02, 0.7}, {0.98, 0.7}}});
  auto w = std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), V(2, 1)));
  SimulatorSettings settings;
  settings.sensors.max_range = 0.15;
  settings.sensors.noise_stddev = noise;
  return Simulator(std::make_shared<const WorldTimeline>(w, std::vector<WorldEvent>{}),
                   std::make_shared<const HolonomicDisc>(HolonomicDiscSettings{0.05, 1.0}), RobotState{start}, settings);
}

TEST(StraightLeg, ArrivesExactlyInTheOpen) {
  Simulator sim = make_sim(V(0.2, 0.2));
  core::Rng rng(1);
  std::vector<V> trace;
  const LegResult r = drive_straight(sim, V(0.8, 0.5), 0.05, {0.025, 20, 3.0}, rng, nullptr, &trace);
  EXPECT_EQ(r.end, LegEnd::kArrived);
  EXPECT_EQ(sim.state().position, V(0.8, 0.5));
  EXPECT_NEAR(r.travelled, (V(0.8, 0.5) - V(0.2, 0.2)).norm(), 1e-12);
  EXPECT_EQ(r.steps, 14u);  // ceil(0.6708 / 0.05)
  EXPECT_EQ(trace.size(), r.steps);
}

TEST(StraightLeg, WallAheadIsSensedBeforeContact) {
  Simulator sim = make_sim(V(0.5, 0.3));
  core::Rng rng(1);
  std::vector<V> trace;
  // A block distance longer than a step: the robot sees the wall before its next step would reach it.
  const LegResult r = drive_straight(sim, V(1.5, 0.3), 0.05, {0.06, 20, 3.0}, rng, nullptr, &trace);
  EXPECT_EQ(r.end, LegEnd::kBlocked);
  // Stopped short of the wall (its face at x = 0.98, so contact at 0.93), never touching it.
  EXPECT_LT(sim.state().position.x(), 0.93 - 1e-9);
  EXPECT_GT(sim.state().position.x(), 0.93 - 0.06 - 0.05);
  for (const V& p : trace) EXPECT_TRUE(sim.world().disc_free(p, 0.05));
}

TEST(StraightLeg, TouchAloneStopsAtTheWall) {
  Simulator sim = make_sim(V(0.5, 0.3));
  core::Rng rng(1);
  const LegResult r = drive_straight(sim, V(1.5, 0.3), 0.05, {0.0, 20, 3.0}, rng, nullptr, nullptr);
  EXPECT_EQ(r.end, LegEnd::kBlocked);
  EXPECT_NEAR(sim.state().position.x(), 0.93, 1e-5);  // in contact with the wall's face
  EXPECT_TRUE(sim.world().disc_free(sim.state().position, 0.05));
}

TEST(StraightLeg, WallBesideTheWayIsNoBlock) {
  // Along the wall's top edge at clearance 0.02: sensors see it to the side, not ahead.
  Simulator sim = make_sim(V(0.5, 0.77), 0.001);
  core::Rng rng(3);
  const LegResult r = drive_straight(sim, V(1.5, 0.77), 0.05, {0.025, 20, 3.0}, rng, nullptr, nullptr);
  EXPECT_EQ(r.end, LegEnd::kArrived);
}

TEST(StraightLeg, DetourSlidesPastACornerTheLineGrazes) {
  // From (0.5, 0.62) to (1.5, 0.82) the line crosses x = 1 at y = 0.72: the disc (r 0.05) would
  // clip the wall's top corner at (1, 0.7).
  const V from(0.5, 0.62), to(1.5, 0.82);
  {
    Simulator sim = make_sim(from);
    core::Rng rng(1);
    EXPECT_EQ(drive_straight(sim, to, 0.02, {0.025, 20, 3.0}, rng, nullptr, nullptr).end, LegEnd::kBlocked);
  }
  Simulator sim = make_sim(from);
  core::Rng rng(1);
  std::vector<V> trace;
  const LegResult r = drive_straight(sim, to, 0.02, {0.025, 20, 3.0, 0.3}, rng, nullptr, &trace);
  EXPECT_EQ(r.end, LegEnd::kArrived);
  EXPECT_EQ(sim.state().position, to);
  for (const V& p : trace) EXPECT_TRUE(sim.world().disc_free(p, 0.05));
  EXPECT_GT(r.travelled, (to - from).norm());  // the slide is driven, not skipped
}

TEST(StraightLeg, DetourAllowanceStillStopsAtAWall) {
  // Straight at the wall, whose top is 0.4 above the line: sliding 0.1 along it does not get round.
  Simulator sim = make_sim(V(0.5, 0.3));
  core::Rng rng(1);
  std::vector<V> trace;
  const LegResult r = drive_straight(sim, V(1.5, 0.3), 0.02, {0.025, 20, 3.0, 0.1}, rng, nullptr, &trace);
  EXPECT_EQ(r.end, LegEnd::kBlocked);
  EXPECT_LT(sim.state().position.x(), 0.93 + 1e-9);
  // Off the line by at most the allowance (and one step's turn beyond it).
  EXPECT_LT(std::abs(sim.state().position.y() - 0.3), 0.1 + 0.02);
  for (const V& p : trace) EXPECT_TRUE(sim.world().disc_free(p, 0.05));
}

TEST(StraightLeg, DriveBackRetracesABlockedLegToItsStart) {
  const V start(0.5, 0.3);
  Simulator sim = make_sim(start);
  core::Rng rng(1);
  std::vector<V> path{start};
  const LegResult out = drive_straight(sim, V(1.5, 0.3), 0.02, {0.025, 20, 3.0, 0.1}, rng, nullptr, &path);
  ASSERT_EQ(out.end, LegEnd::kBlocked);  // slid along the wall, then gave up
  std::vector<V> back;
  const LegResult r = drive_back(sim, path, 0.02, rng, nullptr, &back);
  EXPECT_EQ(r.end, LegEnd::kArrived);
  EXPECT_EQ(sim.state().position, start);
  EXPECT_NEAR(r.travelled, out.travelled, 1e-9);  // the same way, reversed
  for (const V& p : back) EXPECT_TRUE(sim.world().disc_free(p, 0.05));
}

}  // namespace
}  // namespace amp::nav
