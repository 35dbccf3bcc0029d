// PgcsSession's routes (PgcsRunSettings::trace_legs for the trace): plans on the portal or the trace
// graph, ways along the trace through a route's cells, and what a query leaves out.
#include "amp/nav/pgcs/pgcs_router.hpp"

#include <algorithm>

#include "amp/nav/free_mask.hpp"
#include "amp/nav/pgcs/pgcs_explorer.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"

namespace amp::nav {

namespace {
// Radii round a query end the robot never stood at within which the trace guesses the way is free
// (TraceCorridor::path's reach): less than a wall of any thickness plus the disc on both sides.
constexpr double kGuessReach = 2.0;

RouteSettings route_settings(const PgcsRunSettings& run, double radius) {
  return {run.turn_weight * radius, run.prior_weight * radius, run.attach, run.portals ? run.unverified_weight : 0.0,
          run.suspect_weight};
}
}  // namespace

PgcsRouter::PgcsRouter(const PgcsRunSettings& run, double radius, PgcsExplorer& explorer, const TraceCorridor& corridor)
    : radius_(radius),
      explorer_(explorer),
      corridor_(corridor),
      memory_(radius, run.strikes),
      planner_(route_settings(run, radius)),
      portal_graph_(explorer, memory_, &blocked_now_),
      trace_graph_(explorer, corridor, memory_, &blocked_now_) {}

void PgcsRouter::begin_query() {
  explorer_.adopt_exemplars();
  clear_failures();
}

void PgcsRouter::clear_failures() {
  failed_.clear();
  blocked_now_.clear();
}

Route PgcsRouter::plan(const Eigen::Vector2d& from, const Eigen::Vector2d& target, bool tracing, int back) {
  // Tracing, the start also joins the cluster whose cell it stands in, by the trace (its nearest
  // centres' cells may lie beyond a wall).
  const int joined = tracing && back < 0 ? trace_graph_.home(from) : back;
  RouteGraph& graph = tracing ? static_cast<RouteGraph&>(trace_graph_) : portal_graph_;
  return planner_.plan(graph, from, target, {failed_, radius_, joined});
}

int PgcsRouter::label_at(const Eigen::Vector2d& p) { return trace_graph_.cell_label(corridor_.geometry().cell_of(p)); }

PgcsRouter::Traced PgcsRouter::trace_route(const Route& route, const Eigen::Vector2d& from, const Eigen::Vector2d& target,
                                           std::vector<Eigen::Vector2d>& way) {
  std::size_t ids = 0;
  for (int k : explorer_.clusters().ids()) ids = std::max(ids, static_cast<std::size_t>(k) + 1);
  in_route_.assign(ids, 0);
  // The corridor: the cells of the route's clusters, and those of the clusters the two ends stand
  // in, each with the clusters the trace links it to: a cell that straddles a wall may be passed
  // through its neighbour's.
  const int at_from = label_at(from), at_target = label_at(target);
  ring_.clear();
  for (int k : route.nodes) ring_.push_back(k), trace_graph_.append_links(k, ring_);
  ring_.push_back(at_from), trace_graph_.append_links(at_from, ring_);
  ring_.push_back(at_target);
  for (int k : ring_) {
    if (k >= 0 && static_cast<std::size_t>(k) < ids) in_route_[static_cast<std::size_t>(k)] = 1;
  }
  way = corridor_.path(from, target, kGuessReach * radius_, [&](int cell) {
    const int k = trace_graph_.cell_label(cell);
    return k >= 0 && in_route_[static_cast<std::size_t>(k)] != 0;
  });
  if (!way.empty()) return Traced::kDriven;
  return leave_out_unjoined(route, from, target, at_from);
}

PgcsRouter::Traced PgcsRouter::leave_out_unjoined(const Route& route, const Eigen::Vector2d& from,
                                                  const Eigen::Vector2d& target, int at_from) {
  // The first route edge the trace does not support, i.e. the first cluster of the route whose
  // cells a flood from the robot through the route's cells so far does not reach, is left out of
  // this query (its link to the route's previous node), without driving it.
  route_labels_.assign(route.nodes.begin() + 1, route.nodes.end() - 1);
  const std::size_t miss = corridor_.first_unreached(
      from, target, kGuessReach * radius_, at_from, route_labels_, [this](int cell) { return trace_graph_.cell_label(cell); },
      [this](int k, std::vector<int>& out) { trace_graph_.append_links(k, out); });
  if (miss > route_labels_.size()) return Traced::kNone;
  const int a = miss == 0 ? Route::kStart : route_labels_[miss - 1];
  const int b = miss == route_labels_.size() ? Route::kTarget : route_labels_[miss];
  if (a >= 0 && b >= 0) {
    blocked_now_.mark(a, b, explorer_.node_point(a), explorer_.node_point(b));
  } else {
    fail_end(a, b, from, target);
  }
  return Traced::kLeftOut;
}

PgcsRouter::Traced PgcsRouter::trace_anywhere(const Eigen::Vector2d& from, const Eigen::Vector2d& target,
                                              std::vector<Eigen::Vector2d>& way) {
  way = corridor_.path(from, target, kGuessReach * radius_, [](int) { return true; });
  return way.empty() ? Traced::kNone : Traced::kDriven;
}

void PgcsRouter::strike(int a, int b) { memory_.mark(a, b, explorer_.node_point(a), explorer_.node_point(b)); }

void PgcsRouter::drop_portal(int a, int b) {
  explorer_.drop_portal(a, b);
  blocked_now_.mark(a, b, explorer_.node_point(a), explorer_.node_point(b));
}

void PgcsRouter::fail_end(int a, int b, const Eigen::Vector2d& from, const Eigen::Vector2d& target) {
  if (b == Route::kTarget) {
    failed_.push_back({a >= 0 ? target : from, a >= 0 ? a : Route::kTarget});
  } else {
    failed_.push_back({from, b});
  }
}

}  // namespace amp::nav
