#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/pgcs/edge_memory.hpp"
#include "amp/nav/pgcs/pgcs_run_settings.hpp"
#include "amp/nav/pgcs/portal_graph.hpp"
#include "amp/nav/pgcs/route_planner.hpp"
#include "amp/nav/pgcs/trace_graph.hpp"

namespace amp::nav {

class PgcsExplorer;
class TraceCorridor;

// The route graph of a PGCS session's queries: plans on the learned graph (RoutePlanner), either as
// the explorer crossed it (PortalGraph) or as the robot's trace joins it (TraceGraph), less the
// edges found blocked (EdgeMemory, kept across queries: illegal at the `strikes`-th block) and what
// failed in the query under way (edges left out, failed attachments). Along the trace, it also finds
// the way through a route's cells, or says which route edge the trace does not support.
class PgcsRouter {
 public:
  // Whether a way along the trace was found (kDriven), a route edge was left out of this query as
  // the trace does not join it (kLeftOut), or neither (kNone).
  enum class Traced { kDriven, kLeftOut, kNone };

  // `radius`: the robot's; routes' weights are in radii.
  PgcsRouter(const PgcsRunSettings& run, double radius, PgcsExplorer& explorer, const TraceCorridor& corridor);

  const EdgeMemory& memory() const { return memory_; }
  // A new query: exemplars brought up to date, nothing failed yet.
  void begin_query();
  // Forgets what this query left out or saw fail (blocked edges stay remembered).
  void clear_failures();
  // The trace graph's links made afresh when the clusters or the trace changed.
  void link_trace() { trace_graph_.link(); }

  // An optimal route from `from` to `target` on the trace graph (`tracing`) or the portal graph;
  // `back`: the cluster the robot last drove from (-1: none).
  Route plan(const Eigen::Vector2d& from, const Eigen::Vector2d& target, bool tracing, int back);
  // `way` along the trace from `from` to `target` through the cells of the route's clusters
  // (kDriven); else the first route edge the trace does not join is left out (kLeftOut), or kNone.
  Traced trace_route(const Route& route, const Eigen::Vector2d& from, const Eigen::Vector2d& target,
                     std::vector<Eigen::Vector2d>& way);
  // `way` along the trace from `from` to `target` through any visited cells (kDriven), or kNone.
  Traced trace_anywhere(const Eigen::Vector2d& from, const Eigen::Vector2d& target, std::vector<Eigen::Vector2d>& way);
  // The cluster whose cell (on the trace's raster) holds p; -1 outside.
  int label_at(const Eigen::Vector2d& p);

  // A block on the edge between clusters a and b: one strike (illegal at the `strikes`-th).
  void strike(int a, int b);
  // The portal of a-b proved undrivable: dropped, and the edge left out of this query.
  void drop_portal(int a, int b);
  // The leg a -> b with an end off the graph (Route::kStart, Route::kTarget) failed, driven from
  // `from`: that attachment is left out of this query.
  void fail_end(int a, int b, const Eigen::Vector2d& from, const Eigen::Vector2d& target);

 private:
  // The first route edge the trace does not join, left out of this query; kNone when it joins them all.
  Traced leave_out_unjoined(const Route& route, const Eigen::Vector2d& from, const Eigen::Vector2d& target,
                            int at_from);

  double radius_;
  PgcsExplorer& explorer_;
  const TraceCorridor& corridor_;
  EdgeMemory memory_;
  EdgeMemory blocked_now_{0.0};  // verified edges blocked in the query under way
  std::vector<FailedAttachment> failed_;
  RoutePlanner planner_;
  PortalGraph portal_graph_;
  TraceGraph trace_graph_;
  std::vector<std::uint8_t> in_route_;  // by cluster id: on the route being driven
  std::vector<int> route_labels_;       // the route's clusters, in order
  std::vector<int> ring_;               // the corridor's clusters
};

}  // namespace amp::nav
