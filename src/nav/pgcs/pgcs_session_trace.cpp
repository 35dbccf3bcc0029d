// PgcsSession's routes along the robot's trace (PgcsRunSettings::trace_legs): the cells' clusters,
// the clusters the trace links, and a route turned into legs along the trace or an edge left out.
#include <algorithm>

#include "amp/nav/pgcs/pgcs_session.hpp"

namespace amp::nav {

namespace {
// Radii round a query end the robot never stood at within which the trace guesses the way is free
// (TraceCorridor::path's reach): less than a wall of any thickness plus the disc on both sides.
constexpr double kGuessReach = 2.0;
}  // namespace

int PgcsSession::cell_label(int cell) {
  if (cell < 0) return -1;
  if (label_step_ != pgcs_.steps()) {
    label_.assign(trace_.geometry().cell_count(), -2);
    label_step_ = pgcs_.steps();
  }
  int& l = label_[static_cast<std::size_t>(cell)];
  if (l == -2) l = pgcs_.triangulation().nearest(trace_.geometry().cell_center(cell));
  return l;
}

void PgcsSession::link_trace() {
  if (links_step_ == pgcs_.steps() && links_version_ == trace_.version()) return;
  std::size_t ids = 0;
  for (int k : pgcs_.ids()) ids = std::max(ids, static_cast<std::size_t>(k) + 1);
  for (auto& l : trace_links_) l.clear();
  trace_links_.resize(ids);
  const FreeMask& g = trace_.geometry();
  const auto link = [&](int a, int b) {
    if (a < 0 || b < 0 || a == b) return;
    trace_links_[static_cast<std::size_t>(a)].push_back(b);
    trace_links_[static_cast<std::size_t>(b)].push_back(a);
  };
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const int c = g.index(x, y);
      if (!trace_.visited(c)) continue;
      if (x + 1 < g.width() && trace_.visited(c + 1)) link(cell_label(c), cell_label(c + 1));
      if (y + 1 < g.height() && trace_.visited(c + g.width())) link(cell_label(c), cell_label(c + g.width()));
    }
  }
  for (auto& l : trace_links_) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  links_step_ = pgcs_.steps();
  links_version_ = trace_.version();
  trace_key_ = ++graph_key_;
}

int PgcsSession::traced_home(const Eigen::Vector2d& p) {
  const int k = cell_label(trace_.geometry().cell_of(p));
  return k >= 0 && node_point(k).allFinite() ? k : -1;  // a cluster with no point is not in the graph
}

bool PgcsSession::trace_linked(int a, int b) const {
  if (a < 0 || static_cast<std::size_t>(a) >= trace_links_.size()) return false;
  const std::vector<int>& l = trace_links_[static_cast<std::size_t>(a)];
  return std::binary_search(l.begin(), l.end(), b);
}

PgcsSession::Traced PgcsSession::trace_route(const Route& route, const Eigen::Vector2d& from, const Eigen::Vector2d& target) {
  const FreeMask& g = trace_.geometry();
  const double reach = kGuessReach * task_.robot_radius;
  std::size_t ids = 0;
  for (int k : pgcs_.ids()) ids = std::max(ids, static_cast<std::size_t>(k) + 1);
  in_route_.assign(ids, 0);
  const auto admit = [&](int k) {
    if (k >= 0 && static_cast<std::size_t>(k) < ids) in_route_[static_cast<std::size_t>(k)] = 1;
  };
  // The corridor: the cells of the route's clusters, and those of the clusters the two ends stand in,
  const int at_from = cell_label(g.cell_of(from)), at_target = cell_label(g.cell_of(target));
  // Each with the clusters the trace links it to: a cell that straddles a wall may be passed
  // through its neighbour's.
  const auto links = [this](int k, std::vector<int>& out) {
    if (k >= 0 && static_cast<std::size_t>(k) < trace_links_.size()) {
      out.insert(out.end(), trace_links_[static_cast<std::size_t>(k)].begin(), trace_links_[static_cast<std::size_t>(k)].end());
    }
  };
  ring_.clear();
  for (int k : route.nodes) ring_.push_back(k), links(k, ring_);
  ring_.push_back(at_from), links(at_from, ring_);
  ring_.push_back(at_target);
  for (int k : ring_) admit(k);
  const std::vector<Eigen::Vector2d> way = trace_.path(from, target, reach, [&](int cell) {
    const int k = cell_label(cell);
    return k >= 0 && in_route_[static_cast<std::size_t>(k)] != 0;
  });
  if (!way.empty()) {
    for (std::size_t i = 1; i < way.size(); ++i) {
      legs_.push_back({way[i], cell_label(g.cell_of(way[i - 1])), cell_label(g.cell_of(way[i])), Leg::kTrace});
    }
    return Traced::kDriven;
  }
  // No known way: the first route edge the trace does not support, i.e. the first cluster of the
  // route whose cells a flood from the robot through the route's cells so far does not reach, is
  // left out of this query (its link to the route's previous node), without driving it.
  route_labels_.assign(route.nodes.begin() + 1, route.nodes.end() - 1);
  const std::size_t miss = trace_.first_unreached(from, target, reach, at_from, route_labels_,
                                                  [this](int cell) { return cell_label(cell); }, links);
  if (miss > route_labels_.size()) return Traced::kNone;
  const int a = miss == 0 ? Route::kStart : route_labels_[miss - 1];
  const int b = miss == route_labels_.size() ? Route::kTarget : route_labels_[miss];
  if (a >= 0 && b >= 0) {
    blocked_now_.mark(a, b, node_point(a), node_point(b));
  } else if (b == Route::kTarget) {
    failed_.push_back({a >= 0 ? target : from, a >= 0 ? a : Route::kTarget});
  } else {
    failed_.push_back({from, b});
  }
  return Traced::kLeftOut;
}

PgcsSession::Traced PgcsSession::trace_anywhere(const Eigen::Vector2d& from, const Eigen::Vector2d& target) {
  const FreeMask& g = trace_.geometry();
  const std::vector<Eigen::Vector2d> way = trace_.path(from, target, kGuessReach * task_.robot_radius, [](int) { return true; });
  if (way.empty()) return Traced::kNone;
  for (std::size_t i = 1; i < way.size(); ++i) {
    legs_.push_back({way[i], cell_label(g.cell_of(way[i - 1])), cell_label(g.cell_of(way[i])), Leg::kTrace});
  }
  return Traced::kDriven;
}

}  // namespace amp::nav
