#pragma once
// Shared by the PGCS part tests: a session's exploring parts, made as PgcsSession makes them, in two
// 2 m x 2 m rooms side by side joined by a 0.4 m door at the top of the wall between them.
#include <cstdint>
#include <memory>
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/nav/free_mask.hpp"
#include "amp/nav/holonomic_disc.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/pgcs/pgcs_explorer.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav::pgcs_test {

inline NavTask two_rooms() {
  world::Shapes2d s;
  s.polygons.push_back({{{1.95, 0.0}, {2.05, 0.0}, {2.05, 1.6}, {1.95, 1.6}}});
  NavTask t;
  t.name = "two rooms";
  t.robot_radius = 0.05;
  t.start = Eigen::Vector2d(0.5, 1.0);
  t.goal = t.start;
  t.timeline = std::make_shared<const WorldTimeline>(
      std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 2))),
      std::vector<WorldEvent>{});
  return t;
}

// A short run for tests on the bundled maps: `steps` of exploration, `queries` pairs, few curve points.
inline PgcsRunSettings short_run(long steps, int queries) {
  PgcsRunSettings run;
  run.steps = steps;
  run.queries = queries;
  run.curve_points = 10;
  return run;
}

inline PgcsRunSettings small_run(bool portals) {
  PgcsRunSettings r;
  r.steps = 5000;
  r.portals = portals;
  return r;
}

inline learn::PgcsSettings small_pgcs() {
  learn::PgcsSettings p;
  p.max_clusters = 30;
  p.insert_every = 50;
  p.delete_every = 1000;
  return p;
}

inline Simulator disc_simulator(const NavTask& task, const PgcsRunSettings& run) {
  SimulatorSettings s;
  const double r = task.robot_radius;
  return Simulator(task.timeline, std::make_shared<const HolonomicDisc>(HolonomicDiscSettings{r, run.speed * r / s.time_step}),
                   RobotState{task.start}, s);
}

// A robot exploring the two rooms; its trace on a raster of the robot's radius.
struct Exploring {
  NavTask task = two_rooms();
  PgcsRunSettings run;
  Simulator sim;
  TraceCorridor corridor;
  PgcsExplorer explorer;
  explicit Exploring(std::uint64_t seed, bool portals = true)
      : run(small_run(portals)),
        sim(disc_simulator(task, run)),
        corridor(FreeMask(80, 40, 0.05, Eigen::Vector2d(0, 0))),
        explorer(task, run, small_pgcs(), core::Rng(seed)) {}
  void explore(long steps) {
    for (long i = 0; i < steps; ++i) explorer.step(sim, corridor);
  }
};

}  // namespace amp::nav::pgcs_test
