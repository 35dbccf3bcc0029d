#include "amp/nav/pgcs/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "amp/core/error.hpp"
#include "amp/learn/pgcs.hpp"

namespace amp::nav {

namespace {
// Turning angle in [0, pi] from heading a to heading b (radians); headings of null arcs are NaN
// and turn nothing. Headings are taken once per arc (atan2 per relaxation dominated the search).
double turn_angle(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return 0.0;
  const double d = std::abs(b - a);
  return d > std::numbers::pi ? 2.0 * std::numbers::pi - d : d;
}
}  // namespace

RoutePlanner::RoutePlanner(RouteSettings settings) : settings_(settings) {
  if (!(settings_.turn_weight >= 0.0) || !std::isfinite(settings_.turn_weight)) {
    throw ParameterError("turn_weight must be a finite number >= 0");
  }
  if (!(settings_.prior_weight >= 0.0) || !std::isfinite(settings_.prior_weight)) {
    throw ParameterError("prior_weight must be a finite number >= 0");
  }
  if (settings_.attach < 1) throw ParameterError("attach must be >= 1");
  if (!(settings_.unverified_weight >= 0.0) || !std::isfinite(settings_.unverified_weight)) {
    throw ParameterError("unverified_weight must be a finite number >= 0");
  }
  if (!(settings_.suspect_weight >= 0.0) || !std::isfinite(settings_.suspect_weight)) {
    throw ParameterError("suspect_weight must be a finite number >= 0");
  }
}

// The search's small steps, defined before their callers so that the compiler inlines them (out of
// line, a plan on the office map's 1,000 clusters took about 15% longer).
inline const Eigen::Vector2d& RoutePlanner::point(int v) const { return v < s_ ? graph_->at(v) : ends_[v - s_]; }

inline double RoutePlanner::penalty(int w) const {
  if (w >= s_ || settings_.prior_weight == 0.0) return 0.0;  // the start and the target have none
  const double excess = graph_->prior_excess(w);
  // A cluster never visited (prior 0) is a last resort.
  return std::isinf(excess) ? std::numeric_limits<double>::max() / 4 : settings_.prior_weight * excess;
}

inline double RoutePlanner::h(int v) {
  double& d = h_[static_cast<std::size_t>(v)];
  if (d < 0.0) d = (point(v) - ends_[1]).norm();
  return d;
}

// Arrivals dominated by an expanded one at the same node are not searched on. Arriving with heading
// x instead of y changes any next turn by at most angle(x, y) (a triangle inequality on the circle;
// pi when either is a null arc's), so an arrival b with g(b) + turn_weight * angle(a, b) < g(a)
// makes every way on from a dearer than the same way from b. best_in_ (the cheapest expanded
// arrival, with the largest angle, pi) settles most cases before the list.
inline bool RoutePlanner::dominated(int v, double heading, double c) const {
  if (best_in_[static_cast<std::size_t>(v)] + settings_.turn_weight * std::numbers::pi < c) return true;
  for (int b = in_head_[static_cast<std::size_t>(v)]; b >= 0; b = in_next_[static_cast<std::size_t>(b)]) {
    const double other = arcs_[static_cast<std::size_t>(b)].heading;
    const double angle = std::isnan(heading) || std::isnan(other) ? std::numbers::pi : turn_angle(heading, other);
    if (g_[static_cast<std::size_t>(b)] + settings_.turn_weight * angle < c) return true;
  }
  return false;
}

inline void RoutePlanner::relax(int from_arc, int a, double c) {
  const auto ua = static_cast<std::size_t>(a);
  if (c >= g_[ua]) return;
  if (dominated(arcs_[ua].to, arcs_[ua].heading, c)) return;
  g_[ua] = c;
  parent_[ua] = from_arc;
  heap_.push({c + h(arcs_[ua].to), a});
}

inline void RoutePlanner::grow() {
  g_.resize(arcs_.size(), std::numeric_limits<double>::infinity());
  parent_.resize(arcs_.size(), -1);
  closed_.resize(arcs_.size(), 0);
  in_next_.resize(arcs_.size(), -1);
}

Route RoutePlanner::plan(RouteGraph& graph, const Eigen::Vector2d& start, const Eigen::Vector2d& target,
                         const RouteEnds& ends) {
  begin(graph, start, target);
  join_ends(ends);
  Route route;
  const int goal_arc = search(route.expanded);
  if (goal_arc >= 0) trace_back(goal_arc, route);
  return route;
}

void RoutePlanner::begin(RouteGraph& graph, const Eigen::Vector2d& start, const Eigen::Vector2d& target) {
  graph.refresh();
  graph_ = &graph;
  s_ = graph.size();
  ends_[0] = start;
  ends_[1] = target;
  const auto n = static_cast<std::size_t>(s_ + 2);
  arcs_.clear();
  arcs_begin_.assign(n, -1);
  arcs_end_.assign(n, -1);
  links_target_.assign(n, 0);
  g_.clear();
  parent_.clear();
  closed_.clear();
  in_next_.clear();
  heap_.clear();
  h_.assign(n, -1.0);
  best_in_.assign(n, std::numeric_limits<double>::infinity());
  in_head_.assign(n, -1);
}

void RoutePlanner::nearest_nodes(const Eigen::Vector2d& p, const RouteEnds& ends, std::vector<int>& out) {
  auto& by = by_distance_;
  by.clear();
  const double tol2 = ends.tolerance * ends.tolerance;
  for (int i = 0; i < s_; ++i) {
    const int id = graph_->id(i);
    if (graph_->clusters().triangulation().hidden(id)) continue;  // a duplicate: its twin stands for it
    if (!std::isfinite(point(i).x())) continue;                   // left out by the graph
    const bool excluded = std::any_of(ends.failed.begin(), ends.failed.end(), [&](const FailedAttachment& f) {
      return f.cluster == id && (f.point - p).squaredNorm() <= tol2;
    });
    if (!excluded) by.emplace_back((point(i) - p).squaredNorm(), i);
  }
  const std::size_t k = std::min(by.size(), static_cast<std::size_t>(settings_.attach));
  std::partial_sort(by.begin(), by.begin() + static_cast<std::ptrdiff_t>(k), by.end());
  out.clear();
  for (std::size_t i = 0; i < k; ++i) out.push_back(by[i].second);
}

void RoutePlanner::join_ends(const RouteEnds& ends) {
  const int s = s_, t = s_ + 1;
  const Eigen::Vector2d &start = ends_[0], &target = ends_[1];
  nearest_nodes(start, ends, start_links_);
  nearest_nodes(target, ends, target_links_);
  // Straight from start to target only when the target is nearer than every node the start joins.
  const double direct2 = (target - start).squaredNorm();
  const bool direct_failed = std::any_of(ends.failed.begin(), ends.failed.end(), [&](const FailedAttachment& f) {
    return f.cluster == Route::kTarget && (f.point - start).squaredNorm() <= ends.tolerance * ends.tolerance;
  });
  const bool direct = !direct_failed && (start_links_.empty() || direct2 <= (point(start_links_.front()) - start).squaredNorm());
  for (int v : target_links_) links_target_[v] = 1;
  // The start's arcs: to the nodes it joins (unverified but for `back`, the cluster the robot has
  // just driven from), and straight to the target.
  arcs_begin_[s] = 0;
  const double unverified = 1.0 + settings_.unverified_weight;
  for (int w : start_links_) add_arc(s, w, graph_->id(w) == ends.back ? 1.0 : unverified);
  const int back = ends.back >= 0 ? graph_->local(ends.back) : -1;
  if (back >= 0 && std::isfinite(point(back).x()) &&  // a node left out (no point) is not joined
      std::find(start_links_.begin(), start_links_.end(), back) == start_links_.end()) {
    add_arc(s, back, 1.0);
  }
  if (direct) add_arc(s, t, 1.0);
  arcs_end_[s] = static_cast<int>(arcs_.size());
}

void RoutePlanner::add_arc(int v, int w, double factor) {
  const Eigen::Vector2d d = point(w) - point(v);
  const double length = d.norm();
  add_arc(w, length, length > 0.0 ? std::atan2(d.y(), d.x()) : std::nan(""), factor);
}

void RoutePlanner::add_arc(int w, double length, double heading, double factor) {
  arcs_.push_back({w, factor * length + penalty(w), heading});
}

void RoutePlanner::build_arcs(int v) {
  arcs_begin_[v] = static_cast<int>(arcs_.size());
  const EdgeMemory& memory = graph_->memory();
  const EdgeMemory* now = graph_->blocked_now();
  const double unverified = 1.0 + settings_.unverified_weight;
  const bool remembered = !memory.empty(), blocked_now = now != nullptr && !now->empty();
  const int from = graph_->id(v);
  for (const RouteGraph::Neighbour& n : graph_->neighbours(v)) {
    const int id = graph_->id(n.to);
    const int blocks = remembered ? memory.blocks(from, id, point(v), point(n.to)) : 0;
    if (blocks >= memory.strikes()) continue;
    if (blocked_now && now->illegal(from, id, point(v), point(n.to))) continue;
    const bool known = settings_.unverified_weight == 0.0 || n.verified;
    // A suspect (blocked before, not yet illegal) is a last resort.
    add_arc(n.to, n.length, n.heading, (known ? 1.0 : unverified) * (blocks > 0 ? 1.0 + settings_.suspect_weight : 1.0));
  }
  if (links_target_[v] != 0) add_arc(v, s_ + 1, 1.0);
  arcs_end_[v] = static_cast<int>(arcs_.size());
}

// An arc's g is the cost of arriving at its `to` over it, turns included.
int RoutePlanner::search(std::size_t& expanded) {
  const int s = s_, t = s_ + 1;
  grow();
  for (int a = arcs_begin_[s]; a < arcs_end_[s]; ++a) relax(-1, a, arcs_[static_cast<std::size_t>(a)].cost);
  while (!heap_.empty()) {
    const int a = heap_.top().second;
    heap_.pop();
    const auto ua = static_cast<std::size_t>(a);
    if (closed_[ua] != 0) continue;
    closed_[ua] = 1;
    const int v = arcs_[ua].to;
    if (dominated(v, arcs_[ua].heading, g_[ua])) continue;
    double& best = best_in_[static_cast<std::size_t>(v)];
    best = std::min(best, g_[ua]);
    in_next_[ua] = in_head_[static_cast<std::size_t>(v)];
    in_head_[static_cast<std::size_t>(v)] = a;
    ++expanded;
    if (v == t) return a;
    if (arcs_begin_[v] < 0) {
      build_arcs(v);
      grow();
    }
    const double gv = g_[ua];
    const double in = arcs_[ua].heading;
    for (int b = arcs_begin_[v]; b < arcs_end_[v]; ++b) {
      const Arc& out = arcs_[static_cast<std::size_t>(b)];
      relax(a, b, gv + out.cost + settings_.turn_weight * turn_angle(in, out.heading));
    }
  }
  return -1;
}

void RoutePlanner::trace_back(int goal_arc, Route& route) {
  const int s = s_, t = s_ + 1;
  route.cost = g_[static_cast<std::size_t>(goal_arc)];
  scratch_.clear();
  for (int a = goal_arc; a >= 0; a = parent_[static_cast<std::size_t>(a)]) scratch_.push_back(arcs_[static_cast<std::size_t>(a)].to);
  scratch_.push_back(s);
  std::reverse(scratch_.begin(), scratch_.end());
  for (int v : scratch_) {
    route.nodes.push_back(v == s ? Route::kStart : v == t ? Route::kTarget : graph_->id(v));
    route.points.push_back(point(v));
  }
}

}  // namespace amp::nav
