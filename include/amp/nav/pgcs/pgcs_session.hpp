#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"
#include "amp/core/settings_schema.hpp"
#include "amp/learn/pgcs.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/pgcs/edge_memory.hpp"
#include "amp/nav/pgcs/edge_portals.hpp"
#include "amp/nav/pgcs/pgcs_explorer.hpp"
#include "amp/nav/pgcs/pgcs_query_driver.hpp"
#include "amp/nav/pgcs/pgcs_router.hpp"
#include "amp/nav/pgcs/pgcs_run_settings.hpp"
#include "amp/nav/pgcs/reference_worlds.hpp"
#include "amp/nav/pgcs/route_planner.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"
#include "amp/nav/random_walk.hpp"
#include "amp/nav/reference_grid.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::core {
class StopCondition;
}

namespace amp::nav {

// One sample of the exploration curves.
struct CurvePoint {
  long step = 0;
  int clusters = 0;
  double coverage = 0.0;            // share of the reachable free cells within 2 sigma of a centre
  double quantisation_error = 0.0;  // RMS distance from the reachable free cells to their nearest centre
  double closed_prior = 0.0;        // prior mass of clusters the robot can no longer reach (a door closed)
};

// PGCS exploration and trial-and-error queries (Vlassis, Papakonstantinou & Tsanakas): a disc robot
// driven by an exploration strategy streams its positions into learn::Pgcs (PgcsExplorer); queries
// then plan on the centres' Delaunay graph (PgcsRouter, RoutePlanner), drive each leg in the
// simulator, mark blocked edges illegal (EdgeMemory, kept across queries) and replan from where the
// robot stopped (PgcsQueryDriver). The session owns the simulator and the trace they share, and
// samples the exploration curves. Every random draw comes from the session's seed: exploration,
// the query pairs and driving have streams of their own, so two settings that explore differently
// are asked the same queries.
class PgcsSession {
 public:
  // Throws ParameterError for bad settings.
  PgcsSession(NavTask task, PgcsRunSettings run, learn::PgcsSettings pgcs, std::uint64_t seed);
  ~PgcsSession();
  PgcsSession(const PgcsSession&) = delete;  // its parts refer to one another
  PgcsSession& operator=(const PgcsSession&) = delete;

  // Explores `steps` more steps, sampling the curves every steps/curve_points. Returns false when
  // `stop` fired first. `progress(done)` is called at each curve sample.
  bool explore(long steps, const core::StopCondition* stop = nullptr,
               const std::function<void(long done)>& progress = {});
  // `count` pairs of free points, both reachable from the task's start in the world as it is now.
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> draw_queries(int count);
  // Drives from `start` to `target` (the robot is placed at start). Throws ParameterError when a
  // point is outside the world or the disc is not free there.
  QueryRecord query(const Eigen::Vector2d& start, const Eigen::Vector2d& target, const core::StopCondition* stop = nullptr);

  double coverage() const;
  double quantisation_error() const;
  const NavTask& task() const { return task_; }
  const PgcsRunSettings& settings() const { return run_; }
  const learn::Pgcs& clusters() const { return explorer_.clusters(); }
  const EdgeMemory& memory() const { return router_.memory(); }
  const EdgePortals& portals() const { return explorer_.portals(); }
  // The portal of the edge a-b (null when none is known or portals are off).
  const Eigen::Vector2d* portal(int a, int b) const { return explorer_.portal(a, b); }
  // Where the robot drives to reach cluster k: its exemplar (the position in k's Voronoi cell
  // nearest to its centre, a point where the robot has stood), or its centre when exemplars are
  // off. A centre is a mean of positions and may lie inside an obstacle the cluster wraps around
  // (a desk). NaN for a cluster whose cell the robot has not entered since the cluster was made.
  Eigen::Vector2d node_point(int k) const { return explorer_.node_point(k); }
  const std::vector<CurvePoint>& curves() const { return curves_; }
  // Exploration positions, one every few steps (for drawing).
  const std::vector<Eigen::Vector2d>& exploration_trace() const { return explorer_.positions(); }
  const NavWorld& world() const { return simulator_.world(); }
  const ReferenceGrid& reference() const { return worlds_.base(); }
  long steps() const { return explorer_.steps(); }
  // The exploration (for planning on its graph directly, as PortalGraph does).
  const PgcsExplorer& explorer() const { return explorer_; }

 private:
  CurvePoint sample();

  NavTask task_;
  PgcsRunSettings run_;
  // Parts in the order a bad setting or task is found: the PGCS settings, the robot's start, the
  // reference grid.
  PgcsExplorer explorer_;
  Simulator simulator_;
  ReferenceWorlds worlds_;
  TraceCorridor trace_;      // where the robot has stood, on a raster over the reference grid
  PgcsRouter router_;
  PgcsQueryDriver driver_;
  core::Rng query_rng_;
  std::vector<CurvePoint> curves_;
};

}  // namespace amp::nav
