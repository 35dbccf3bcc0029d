#include "amp/nav/simulator.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/holonomic_disc.hpp"
#include "amp/nav/polygon_nav_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
const Eigen::AlignedBox2d kUnitBox(V(0, 0), V(1, 1));

std::shared_ptr<const WorldTimeline> timeline(std::shared_ptr<const NavWorld> w, std::vector<WorldEvent> events = {}) {
  return std::make_shared<const WorldTimeline>(std::move(w), std::move(events));
}

// 1 m square split at x = 0.5 by a wall of no thickness, with a box and a pillar on the left.
std::shared_ptr<const NavWorld> split_polygon_world() {
  world::Shapes2d s;
  s.segments.push_back({{0.5, 0.0}, {0.5, 1.0}});
  s.polygons.push_back({{{0.1, 0.1}, {0.2, 0.1}, {0.2, 0.3}, {0.1, 0.3}}});
  s.circles.push_back({{0.3, 0.8}, 0.05});
  return std::make_shared<const PolygonNavWorld>(s, kUnitBox);
}

// The same on a 40 x 40 map of 2.5 cm cells: a one-cell wall in column 20, a block at the left.
std::shared_ptr<const NavWorld> split_map_world() {
  auto g = std::make_shared<world::OccupancyGrid>(40, 40, 0.025);
  for (int y = 0; y < 40; ++y) g->set_state(20, y, world::CellState::kOccupied);
  for (int y = 4; y < 12; ++y) {
    for (int x = 4; x < 8; ++x) g->set_state(x, y, world::CellState::kOccupied);
  }
  g->set_state(12, 30, world::CellState::kUnknown);
  return std::make_shared<const GridNavWorld>(g);
}

struct Walk {
  std::vector<V> positions;
  std::vector<double> ranges;
  std::size_t blocked = 0;
};

// A random walk that holds each random heading for 10 steps, at 1 m/s with 0.2 s steps: each move
// (20 cm) is far longer than the robot (5.5 cm) plus the wall, so only the advancement keeps the
// robot on its side.
Walk random_walk(std::shared_ptr<const NavWorld> w, std::uint64_t seed, int steps) {
  SimulatorSettings settings;
  settings.time_step = 0.2;
  Simulator sim(timeline(w), std::make_shared<const HolonomicDisc>(HolonomicDiscSettings{0.0275, 1.0}),
                RobotState{V(0.3, 0.5)}, settings);
  core::Rng rng(seed);
  Walk out;
  V command = V::Zero();
  for (int i = 0; i < steps; ++i) {
    if (i % 10 == 0) {
      const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
      command = V(std::cos(a), std::sin(a));
    }
    sim.step(command, rng);
    out.positions.push_back(sim.state().position);
    out.ranges.insert(out.ranges.end(), sim.ranges().begin(), sim.ranges().end());
  }
  out.blocked = sim.blocked_moves();
  return out;
}

void expect_never_overlaps(const std::shared_ptr<const NavWorld>& w, const Walk& walk, double wall_x) {
  for (std::size_t i = 0; i < walk.positions.size(); ++i) {
    ASSERT_TRUE(w->disc_free(walk.positions[i], 0.0275)) << "step " << i;
    ASSERT_LE(walk.positions[i].x(), wall_x - 0.0275) << "crossed the wall at step " << i;
  }
  for (const double r : walk.ranges) ASSERT_TRUE(r >= 0.0 && r <= 0.1);
}

TEST(Simulator, RandomWalkNeverOverlapsOrCrossesAThinWallPolygons) {
  const auto w = split_polygon_world();
  const Walk walk = random_walk(w, 11, 4000);
  expect_never_overlaps(w, walk, 0.5);
  EXPECT_GT(walk.blocked, 100u);  // the walk meets the walls often
}

TEST(Simulator, RandomWalkNeverOverlapsOrCrossesAThinWallMap) {
  const auto w = split_map_world();
  const Walk walk = random_walk(w, 12, 4000);
  expect_never_overlaps(w, walk, 0.5);
  EXPECT_GT(walk.blocked, 100u);
}

TEST(Simulator, SameSeedSameTrajectory) {
  const auto w = split_map_world();
  const Walk a = random_walk(w, 5, 500), b = random_walk(w, 5, 500), c = random_walk(w, 6, 500);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_EQ(a.blocked, b.blocked);
  EXPECT_NE(a.positions, c.positions);
}

SimulatorSettings exact_sensors() {
  SimulatorSettings s;
  s.sensors.noise_stddev = 0.0;
  return s;
}

TEST(Simulator, DrivingIntoAWallIsBlockedAndCounted) {
  const auto w = std::make_shared<const PolygonNavWorld>(world::Shapes2d{}, kUnitBox);
  Simulator sim(timeline(w), std::make_shared<const HolonomicDisc>(), RobotState{V(0.5, 0.5)}, exact_sensors());
  core::Rng rng(1);
  // 1 cm per step (0.1 m/s clipped, 0.1 s): 47 free moves to x = 0.97, then contact at 0.9725.
  for (int i = 0; i < 60; ++i) {
    const StepResult r = sim.step(V(5.0, 0.0), rng);
    EXPECT_EQ(r.blocked, i >= 47) << i;
  }
  EXPECT_EQ(sim.blocked_moves(), 13u);
  EXPECT_GE(sim.state().position.x(), 0.97 - 1e-12);
  EXPECT_LE(sim.state().position.x(), 0.9725);
  EXPECT_NEAR(sim.ranges()[0], 0.9725 - sim.state().position.x(), 1e-12);  // sensor 0 faces the wall
  EXPECT_DOUBLE_EQ(sim.ranges()[4], 0.1);                                   // behind: nothing in range
  // Backing off from contact works.
  const double x = sim.state().position.x();
  const StepResult back = sim.step(V(-1.0, 0.0), rng);
  EXPECT_FALSE(back.blocked);
  EXPECT_NEAR(sim.state().position.x(), x - 0.01, 1e-9);
  EXPECT_EQ(sim.step_count(), 61u);
}

TEST(Simulator, EventsChangeTheReadingsAtTheirStep) {
  const auto w = std::make_shared<const PolygonNavWorld>(world::Shapes2d{}, kUnitBox);
  WorldEvent appear, vanish;
  appear.step = 5;
  appear.change.shapes.circles.push_back({{0.6, 0.5}, 0.02});
  vanish = appear;
  vanish.step = 8;
  vanish.change.action = ObstacleChange::Action::kVanish;
  Simulator sim(timeline(w, {appear, vanish}), std::make_shared<const HolonomicDisc>(), RobotState{V(0.5, 0.5)},
                exact_sensors());
  core::Rng rng(1);
  for (int i = 0; i < 10; ++i) {
    const StepResult r = sim.step(V::Zero(), rng);
    EXPECT_EQ(r.world_changed, i == 5 || i == 8) << i;
    EXPECT_NEAR(sim.ranges()[0], i >= 5 && i < 8 ? 0.0525 : 0.1, 1e-12) << i;
  }
}

TEST(Simulator, AnObstacleAppearingOnTheRobotTrapsItUntilItVanishes) {
  const auto w = std::make_shared<const PolygonNavWorld>(world::Shapes2d{}, kUnitBox);
  WorldEvent appear, vanish;
  appear.step = 3;
  appear.change.shapes.circles.push_back({{0.5, 0.5}, 0.01});
  vanish = appear;
  vanish.step = 6;
  vanish.change.action = ObstacleChange::Action::kVanish;
  Simulator sim(timeline(w, {appear, vanish}), std::make_shared<const HolonomicDisc>(), RobotState{V(0.5, 0.5)},
                exact_sensors());
  core::Rng rng(1);
  for (int i = 0; i < 7; ++i) {
    const StepResult r = sim.step(V(1.0, 0.0), rng);
    EXPECT_EQ(r.trapped, i >= 3 && i < 6) << i;
  }
  EXPECT_EQ(sim.blocked_moves(), 3u);
  EXPECT_NEAR(sim.state().position.x(), 0.54, 1e-12);
}

TEST(Simulator, RefusesABadStartAndBadSettings) {
  const auto w = split_polygon_world();
  const auto robot = std::make_shared<const HolonomicDisc>();
  EXPECT_THROW(Simulator(timeline(w), robot, RobotState{V(0.5, 0.5)}), ParameterError);  // on the wall
  SimulatorSettings s;
  s.time_step = 0.0;
  EXPECT_THROW(Simulator(timeline(w), robot, RobotState{V(0.3, 0.5)}, s), ParameterError);
  s = SimulatorSettings{};
  s.contact_tolerance = 0.05;  // more than the radius
  EXPECT_THROW(Simulator(timeline(w), robot, RobotState{V(0.3, 0.5)}, s), ParameterError);
  s = SimulatorSettings{};
  s.sensors.count = 0;
  EXPECT_THROW(Simulator(timeline(w), robot, RobotState{V(0.3, 0.5)}, s), ParameterError);
  EXPECT_THROW(HolonomicDisc(HolonomicDiscSettings{0.0, 1.0}), ParameterError);
}

}  // namespace
}  // namespace amp::nav
