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
#include "amp/nav/pgcs/route_planner.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"
#include "amp/nav/random_walk.hpp"
#include "amp/nav/reference_grid.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::core {
class StopCondition;
}

namespace amp::nav {

// How a PGCS session explores and answers queries; lengths are in robot radii, so one setting
// suits a Khepera in a maze and a wheelchair in an office.
struct PgcsRunSettings {
  long steps = 200000;                       // exploration steps (simulator time steps)
  int queries = 100;                         // random query pairs after exploring
  int curve_points = 100;                    // samples of the curves over the exploration
  std::string exploration = "random-walk";   // random-walk | novelty
  double speed = 0.4;                        // radii per time step
  double turn_every = 50.0;                  // random walk: mean steps between heading changes
  double avoid_distance = 0.5;               // radii: a sensor reading below this turns the walk
  double sensor_range = 1.5;                 // radii beyond the rim
  double sensor_noise = 0.01;                // radii (standard deviation)
  double turn_weight = 1.0;                  // route cost per radian turned, in radii
  double prior_weight = 1.0;                 // route cost per unit of log(mean prior / prior), in radii
  int attach = 3;                            // start and target join this many nearest centres
  int max_replans = 100;                     // a query gives up after this many replans (a safety net)
  double block_distance = 0.5;               // radii: a sensor reading ahead below this is a block
  // Radii a leg may slide off its line past a block (StraightLegSettings::detour). 4: legs that
  // graze a door frame get through; queries solved with 0 against 4 (6 seeds): office 97.5% and
  // 99.2%, MovingAI rooms (novelty walk, l = 50,000, M = 300) 39% and 70%.
  double detour = 4.0;
  // Blocks before an edge is illegal (EdgeMemory); 2: a blocked edge stays a last resort once (a
  // leg that clipped a door frame cut whole rooms off the MovingAI rooms map with 1).
  int strikes = 2;
  double suspect_weight = 100.0;             // extra route cost per length of an edge blocked, not yet illegal
  bool retreat = true;                       // after a block, drive back the way the leg came, then replan
  double reference_cell = 0.0;               // m, the reference grid's cell; 0: longer side / 256
  bool portals = true;                       // drive an edge through where the explorer crossed it (EdgePortals)
  double unverified_weight = 1.0;            // extra route cost per length of an edge never seen crossed
  bool exemplars = true;                     // drive to each cluster's exemplar, not to its centre
  bool shortcuts = true;                     // between two portals, cut across the cell (not via its point)
  // Drive a route along the positions the robot has stood at in its clusters' cells (TraceCorridor),
  // falling back to the legs above when they do not join.
  bool trace_legs = true;
  static const core::SettingsSchema<PgcsRunSettings>& schema();
  void validate() const { schema().validate(*this); }
};

// One sample of the exploration curves.
struct CurvePoint {
  long step = 0;
  int clusters = 0;
  double coverage = 0.0;            // share of the reachable free cells within 2 sigma of a centre
  double quantisation_error = 0.0;  // RMS distance from the reachable free cells to their nearest centre
  double closed_prior = 0.0;        // prior mass of clusters the robot can no longer reach (a door closed)
};

// One query driven by trial and error.
struct QueryRecord {
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), target = Eigen::Vector2d::Zero();
  bool solved = false;
  bool unsolvable = false;  // the graph, less its illegal edges, does not join them (no route left)
  int replans = 0;
  int left_out = 0;         // route edges left out, undriven, as the trace does not join them (trace_legs)
  double length = 0.0;      // driven
  double shortest = 0.0;    // grid-shortest in the world at query time (+inf: not connected)
  double ratio = 0.0;       // length / shortest when solved, else 0
  double plan_time_s = 0.0; // route planning, not driving (the A* calls and the trace searches)
  std::size_t illegal_edges = 0;            // known after this query
  std::vector<Eigen::Vector2d> trace;       // driven positions
  std::vector<Eigen::Vector2d> blocks;      // where the robot stopped and replanned
};

// PGCS exploration and trial-and-error queries (Vlassis, Papakonstantinou & Tsanakas): a disc robot
// driven by an exploration strategy streams its positions into learn::Pgcs; queries then plan on the
// centres' Delaunay graph (RoutePlanner), drive each leg in the simulator, mark blocked edges
// illegal (EdgeMemory, kept across queries) and replan from where the robot stopped. Every random
// draw comes from the session's seed: exploration and the query pairs have streams of their own,
// so two settings that explore differently are asked the same queries.
class PgcsSession {
 public:
  // Throws ParameterError for bad settings.
  PgcsSession(NavTask task, PgcsRunSettings run, learn::PgcsSettings pgcs, std::uint64_t seed);
  ~PgcsSession();

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
  const learn::Pgcs& clusters() const { return pgcs_; }
  const EdgeMemory& memory() const { return memory_; }
  const EdgePortals& portals() const { return portals_; }
  // The portal of the edge a-b (null when none is known or portals are off).
  const Eigen::Vector2d* portal(int a, int b) const;
  // Where the robot drives to reach cluster k: its exemplar (the position in k's Voronoi cell
  // nearest to its centre, a point where the robot has stood), or its centre when exemplars are
  // off. A centre is a mean of positions and may lie inside an obstacle the cluster wraps around
  // (a desk). NaN for a cluster whose cell the robot has not entered since the cluster was made.
  Eigen::Vector2d node_point(int k) const;
  const std::vector<CurvePoint>& curves() const { return curves_; }
  // Exploration positions, one every few steps (for drawing).
  const std::vector<Eigen::Vector2d>& exploration_trace() const { return explored_; }
  const NavWorld& world() const { return simulator_.world(); }
  const ReferenceGrid& reference() const { return reference_; }
  long steps() const { return explore_steps_; }

 private:
  CurvePoint sample();
  // Notes births of clusters (after PGCS's insertions and deletions) and the crossing of this step.
  void track_clusters();
  // The free cells reachable from the task's start in the current world (cached per world version).
  const std::vector<std::uint8_t>& reachable();

  NavTask task_;
  PgcsRunSettings run_;
  learn::Pgcs pgcs_;
  EdgeMemory memory_;
  EdgePortals portals_;
  std::vector<long> born_;        // by cluster id: the step it was (last) created
  std::vector<Eigen::Vector2d> exemplar_;  // by cluster id
  std::vector<long> exemplar_born_;        // by cluster id: born_ of the cluster the exemplar is of
  std::vector<std::uint8_t> alive_;  // by cluster id, as of the last check
  int last_winner_ = -1;
  Eigen::Vector2d last_position_ = Eigen::Vector2d::Zero();
  RoutePlanner planner_;
  core::Rng explore_rng_, query_rng_, drive_rng_;
  Simulator simulator_;
  RandomWalk walk_;
  ReferenceGrid reference_;  // of the base world (coverage and quantisation error)
  TraceCorridor trace_;      // where the robot has stood, on the reference grid's raster
  std::vector<int> label_;   // per raster cell: the nearest cluster (-2: not yet asked), for label_step_
  long label_step_ = -1;
  std::vector<std::uint8_t> in_route_;  // by cluster id: on the route being driven
  std::vector<int> route_labels_;       // the route's clusters, in order
  std::vector<int> ring_;               // the corridor's clusters
  // By cluster id: the clusters whose cells the trace joins to its cells side by side (sorted),
  // for the clusters of links_step_ and the trace of links_version_.
  std::vector<std::vector<int>> trace_links_;
  long links_step_ = -1;
  std::uint64_t links_version_ = 0;
  // RoutePlanner's graph_keys, drawn from one counter so that no two graphs share one. trace_key_:
  // the tracing plans' graph, new whenever trace_links_ are made afresh (the clusters, their points
  // and the links hold until then). The portal graph's key (a query's own) is new at each query and
  // whenever a portal is dropped.
  std::uint64_t graph_key_ = 0, trace_key_ = 0;
  void link_trace();
  bool trace_linked(int a, int b) const;
  // The cluster whose cell holds p, when it has a point to drive to (else -1).
  int traced_home(const Eigen::Vector2d& p);
  // The cluster whose cell holds raster cell `cell` (cached while the clusters stand still).
  int cell_label(int cell);
  // kDriven: legs_ follow the trace through the route's cells. kLeftOut: the trace does not join
  // them, and the first route edge it does not join is left out of this query. kNone: neither.
  enum class Traced { kDriven, kLeftOut, kNone };
  Traced trace_route(const Route& route, const Eigen::Vector2d& from, const Eigen::Vector2d& target);
  // legs_ along the trace from `from` to `target` through any visited cells (kDriven), or kNone.
  Traced trace_anywhere(const Eigen::Vector2d& from, const Eigen::Vector2d& target);
  std::vector<std::uint8_t> base_reachable_;
  std::unique_ptr<ReferenceGrid> current_;   // of the world at the current step (queries, closed prior)
  std::size_t current_version_ = static_cast<std::size_t>(-1);
  std::vector<std::uint8_t> current_reachable_;
  std::vector<CurvePoint> curves_;
  std::vector<Eigen::Vector2d> explored_;
  // Drives back through rec.trace[from - 1 ..] reversed; false when `stop` fired.
  bool retreat(std::size_t from, QueryRecord& rec, const core::StopCondition* stop);
  void adopt_exemplars();  // exemplars from the kept exploration trace, once the clusters stand still
  long exemplars_step_ = -1;  // the clusters' step adopt_exemplars ran at
  std::vector<FailedAttachment> failed_;
  EdgeMemory blocked_now_{0.0};              // verified edges blocked in the query under way
  std::vector<Eigen::Vector2d> path_back_;
  struct Leg {
    enum Kind { kNode, kPortal, kSkipped, kTrace };
    Eigen::Vector2d to;
    int from, to_node;  // the route edge this leg drives
    Kind kind;          // to to_node's point, to the edge's portal, a node cut across, or along the trace
  };
  std::vector<Leg> legs_;
  std::vector<std::uint8_t> was_alive_;
  long explore_steps_ = 0;
  bool last_blocked_ = false;
};

}  // namespace amp::nav
