#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"
#include "amp/nav/pgcs/pgcs_router.hpp"
#include "amp/nav/pgcs/pgcs_run_settings.hpp"
#include "amp/nav/pgcs/route_planner.hpp"
#include "amp/nav/straight_leg.hpp"

namespace amp::core {
class StopCondition;
}

namespace amp::nav {

class PgcsExplorer;
class ReferenceWorlds;
class Simulator;
class TraceCorridor;

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

// A PGCS session's queries (Vlassis, Papakonstantinou & Tsanakas, section 4): plan a route on the
// learned graph (PgcsRouter), drive it leg by leg in the simulator (along the robot's trace when the
// trace joins the route's cells), and on a block mark what blocked (an edge, a portal, an
// attachment, the trace cells ahead), drive back the way the leg came and plan again from there.
class PgcsQueryDriver {
 public:
  // `rng`: the driving's own stream (sensor noise). The parts are the session's and outlive the driver.
  PgcsQueryDriver(const PgcsRunSettings& run, double radius, core::Rng rng, Simulator& simulator,
                  TraceCorridor& corridor, ReferenceWorlds& worlds, PgcsExplorer& explorer, PgcsRouter& router);

  // Drives from `start` to `target` (the robot is placed at start). Throws ParameterError when a
  // point is outside the world or the disc is not free there.
  QueryRecord query(const Eigen::Vector2d& start, const Eigen::Vector2d& target, const core::StopCondition* stop);

 private:
  // A waypoint of the route being driven.
  struct Leg {
    enum Kind { kNode, kPortal, kSkipped, kTrace };
    Eigen::Vector2d to;
    int from, to_node;  // the route edge this leg drives
    Kind kind;          // to to_node's point, to the edge's portal, a node cut across, or along the trace
  };
  // What one query carries from one plan to the next.
  struct Progress {
    Eigen::Vector2d target;
    bool tracing = false;   // routes on the trace graph, driven along the trace
    bool anywhere = false;  // the trace first, wherever it leads; routes on the portal graph
    int left_out = 0;       // route edges left out as not known to the trace
    int back = -1;          // the cluster the robot last drove from
  };
  enum class Planned { kLegs, kAgain, kNoRoute, kStopped };
  enum class Driven { kArrived, kBlocked, kStopped };

  QueryRecord begin(const Eigen::Vector2d& start, const Eigen::Vector2d& target);
  void end(QueryRecord& rec, const Progress& q) const;
  // No route the trace supports: the rest of the query follows the trace wherever it leads.
  void to_anywhere(Progress& q);
  // legs_ for the robot where it stands, or why there are none.
  Planned plan_legs(Progress& q, QueryRecord& rec, const core::StopCondition* stop);
  void legs_along(const Route& route);
  void legs_along_trace();
  // Drives legs_ until one is blocked, all are driven or `stop` fires.
  Driven drive_legs(Progress& q, QueryRecord& rec, const core::StopCondition* stop);
  LegResult drive_leg(const Eigen::Vector2d& to, QueryRecord& rec, const core::StopCondition* stop);
  // What a block of leg li says: marked on the trace, the memory, the portals or the attachments.
  void trace_leg_blocked(std::size_t li, Progress& q, QueryRecord& rec);
  void leg_blocked(const Leg& l, const Eigen::Vector2d& leg_start, Progress& q, QueryRecord& rec);
  // Drives back through rec.trace[from - 1 ..] reversed; false when `stop` fired.
  bool retreat(std::size_t from, QueryRecord& rec, const core::StopCondition* stop);

  const PgcsRunSettings& run_;
  double radius_;
  core::Rng rng_;
  Simulator& simulator_;
  TraceCorridor& corridor_;
  ReferenceWorlds& worlds_;
  PgcsExplorer& explorer_;
  PgcsRouter& router_;
  StraightLegSettings leg_;
  std::vector<Leg> legs_;
  std::vector<Eigen::Vector2d> way_;        // along the trace
  std::vector<Eigen::Vector2d> path_back_;
};

}  // namespace amp::nav
