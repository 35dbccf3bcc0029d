#include "amp/nav/pgcs/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
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

void RoutePlanner::nearest_centres(const learn::Pgcs& clusters, const Eigen::Vector2d& p,
                                   std::span<const FailedAttachment> failed, double tolerance,
                                   std::vector<int>& out) {
  auto& by = by_distance_;
  by.clear();
  const double tol2 = tolerance * tolerance;
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    const int id = ids_[i];
    if (clusters.triangulation().hidden(id)) continue;  // a duplicate: its twin stands for it
    if (!std::isfinite(points_[i].x())) continue;       // left out by the caller
    const bool excluded = std::any_of(failed.begin(), failed.end(), [&](const FailedAttachment& f) {
      return f.cluster == id && (f.point - p).squaredNorm() <= tol2;
    });
    if (!excluded) by.emplace_back((points_[i] - p).squaredNorm(), static_cast<int>(i));
  }
  const std::size_t k = std::min(by.size(), static_cast<std::size_t>(settings_.attach));
  std::partial_sort(by.begin(), by.begin() + static_cast<std::ptrdiff_t>(k), by.end());
  out.clear();
  for (std::size_t i = 0; i < k; ++i) out.push_back(by[i].second);
}

double RoutePlanner::penalty(int w) {
  double& p = penalty_[static_cast<std::size_t>(w)];
  if (std::isnan(p)) {
    const double pi = clusters_->prior(ids_[w]);
    if (settings_.prior_weight == 0.0) {
      p = 0.0;
    } else {
      p = pi > 0.0 ? settings_.prior_weight * std::max(0.0, log_mean_prior_ - std::log(pi))
                   : std::numeric_limits<double>::max() / 4;  // never visited: last resort
    }
  }
  return p;
}

void RoutePlanner::add_arc(int v, int w, double factor) {
  const Eigen::Vector2d d = points_[w] - points_[v];
  const double length = d.norm();
  add_arc(w, length, length > 0.0 ? std::atan2(d.y(), d.x()) : std::nan(""), factor);
}

void RoutePlanner::add_arc(int w, double length, double heading, double factor) {
  arcs_.push_back({w, factor * length + penalty(w), heading});
}

void RoutePlanner::find_neighbours(const learn::Pgcs& clusters, int v, const std::function<bool(int, int)>& verified,
                                   const std::function<void(int, std::vector<int>&)>& more_neighbours) {
  nbr_begin_[v] = static_cast<int>(nbrs_.size());
  clusters.triangulation().neighbours(ids_[v], neighbours_);
  if (more_neighbours) more_neighbours(ids_[v], neighbours_);
  for (int id : neighbours_) {
    if (static_cast<std::size_t>(id) >= local_of_.size() || local_of_[static_cast<std::size_t>(id)] < 0) continue;
    const int w = local_of_[static_cast<std::size_t>(id)];
    if (!std::isfinite(points_[w].x())) continue;
    if (std::any_of(nbrs_.begin() + nbr_begin_[v], nbrs_.end(), [&](const Neighbour& n) { return n.to == w; })) continue;
    const Eigen::Vector2d d = points_[w] - points_[v];
    const double length = d.norm();
    const bool known = settings_.unverified_weight == 0.0 || !verified || verified(ids_[v], id);
    nbrs_.push_back({w, length, length > 0.0 ? std::atan2(d.y(), d.x()) : std::nan(""), known});
  }
  nbr_end_[v] = static_cast<int>(nbrs_.size());
}

void RoutePlanner::build_arcs(const learn::Pgcs& clusters, const EdgeMemory& memory, const EdgeMemory* blocked_now, int v,
                              const std::function<bool(int, int)>& verified,
                              const std::function<void(int, std::vector<int>&)>& more_neighbours) {
  if (nbr_begin_[v] < 0) find_neighbours(clusters, v, verified, more_neighbours);
  arcs_begin_[v] = static_cast<int>(arcs_.size());
  const double unverified = 1.0 + settings_.unverified_weight;
  const bool remembered = !memory.empty(), now = blocked_now != nullptr && !blocked_now->empty();
  for (int i = nbr_begin_[v]; i < nbr_end_[v]; ++i) {
    const Neighbour& n = nbrs_[static_cast<std::size_t>(i)];
    const int id = ids_[n.to];
    const int blocks = remembered ? memory.blocks(ids_[v], id, points_[v], points_[n.to]) : 0;
    if (blocks >= memory.strikes()) continue;
    if (now && blocked_now->illegal(ids_[v], id, points_[v], points_[n.to])) continue;
    // A suspect (blocked before, not yet illegal) is a last resort.
    add_arc(n.to, n.length, n.heading, (n.known ? 1.0 : unverified) * (blocks > 0 ? 1.0 + settings_.suspect_weight : 1.0));
  }
  if (links_target_[v] != 0) add_arc(v, static_cast<int>(points_.size()) - 1, 1.0);
  arcs_end_[v] = static_cast<int>(arcs_.size());
}

Route RoutePlanner::plan(const learn::Pgcs& clusters, const EdgeMemory& memory, const Eigen::Vector2d& start,
                         const Eigen::Vector2d& target, std::span<const FailedAttachment> failed,
                         double failed_tolerance, const std::function<bool(int, int)>& verified,
                         const std::function<Eigen::Vector2d(int)>& where, int back,
                         const std::function<void(int, std::vector<int>&)>& more_neighbours,
                         const EdgeMemory* blocked_now, std::uint64_t graph_key) {
  Route route;
  const std::vector<int>& alive = clusters.ids();
  const int k = static_cast<int>(alive.size());
  const int s = k, t = k + 1, n = k + 2;
  if (graph_key == 0 || graph_key != key_ || ids_.size() != alive.size()) {
    // A new graph: its clusters' local indices, points, prior penalties and neighbours afresh.
    key_ = graph_key;
    ids_.assign(alive.begin(), alive.end());
    const int max_id = alive.empty() ? 0 : alive.back();
    local_of_.assign(static_cast<std::size_t>(max_id) + 1, -1);
    points_.resize(static_cast<std::size_t>(n));
    double prior_sum = 0.0;
    for (int i = 0; i < k; ++i) {
      local_of_[static_cast<std::size_t>(ids_[i])] = i;
      points_[i] = where ? where(ids_[i]) : clusters.mean(ids_[i]);
      prior_sum += clusters.prior(ids_[i]);
    }
    // Prior penalties are taken when a node is first reached (a log per cluster per plan cost more
    // than the search); the start and the target have none.
    log_mean_prior_ = k > 0 && prior_sum > 0.0 ? std::log(prior_sum / k) : 0.0;
    penalty_.assign(static_cast<std::size_t>(n), std::nan(""));
    penalty_[static_cast<std::size_t>(s)] = penalty_[static_cast<std::size_t>(t)] = 0.0;
    nbr_begin_.assign(static_cast<std::size_t>(k), -1);
    nbr_end_.assign(static_cast<std::size_t>(k), -1);
    nbrs_.clear();
  }
  clusters_ = &clusters;
  points_[s] = start;
  points_[t] = target;
  nearest_centres(clusters, start, failed, failed_tolerance, start_links_);
  nearest_centres(clusters, target, failed, failed_tolerance, target_links_);
  // Straight from start to target only when the target is nearer than every centre the start joins.
  const double direct2 = (target - start).squaredNorm();
  const bool direct_failed = std::any_of(failed.begin(), failed.end(), [&](const FailedAttachment& f) {
    return f.cluster == Route::kTarget && (f.point - start).squaredNorm() <= failed_tolerance * failed_tolerance;
  });
  const bool direct = !direct_failed && (start_links_.empty() ||
                                         direct2 <= (points_[start_links_.front()] - start).squaredNorm());

  arcs_.clear();
  arcs_begin_.assign(static_cast<std::size_t>(n), -1);
  arcs_end_.assign(static_cast<std::size_t>(n), -1);
  links_target_.assign(static_cast<std::size_t>(n), 0);
  for (int v : target_links_) links_target_[v] = 1;
  // The start's arcs: to the centres it joins (unverified but for `back`, the cluster the robot
  // has just driven from), and straight to the target.
  arcs_begin_[s] = 0;
  const double unverified = 1.0 + settings_.unverified_weight;
  for (int w : start_links_) add_arc(s, w, ids_[w] == back ? 1.0 : unverified);
  if (back >= 0 && static_cast<std::size_t>(back) < local_of_.size() && local_of_[back] >= 0 &&
      std::isfinite(points_[local_of_[back]].x()) &&  // a cluster left out (no point) is not joined
      std::find(start_links_.begin(), start_links_.end(), local_of_[back]) == start_links_.end()) {
    add_arc(s, local_of_[back], 1.0);
  }
  if (direct) add_arc(s, t, 1.0);
  arcs_end_[s] = static_cast<int>(arcs_.size());

  // A* over arcs: an arc's g is the cost of arriving at its `to` over it, turns included.
  g_.clear();
  parent_.clear();
  closed_.clear();
  in_next_.clear();
  heap_.clear();
  h_.assign(static_cast<std::size_t>(n), -1.0);
  // Arrivals dominated by an expanded one at the same node are not searched on. Arriving with
  // heading x instead of y changes any next turn by at most angle(x, y) (a triangle inequality on
  // the circle; pi when either is a null arc's), so an arrival b with g(b) + turn_weight *
  // angle(a, b) < g(a) makes every way on from a dearer than the same way from b. best_in_ (the
  // cheapest expanded arrival, with the largest angle, pi) settles most cases before the list.
  best_in_.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  in_head_.assign(static_cast<std::size_t>(n), -1);
  const double max_turn = settings_.turn_weight * std::numbers::pi;
  auto dominated = [&](int v, double heading, double c) {
    if (best_in_[static_cast<std::size_t>(v)] + max_turn < c) return true;
    for (int b = in_head_[static_cast<std::size_t>(v)]; b >= 0; b = in_next_[static_cast<std::size_t>(b)]) {
      const double other = arcs_[static_cast<std::size_t>(b)].heading;
      const double angle = std::isnan(heading) || std::isnan(other) ? std::numbers::pi : turn_angle(heading, other);
      if (g_[static_cast<std::size_t>(b)] + settings_.turn_weight * angle < c) return true;
    }
    return false;
  };
  auto h = [&](int v) {  // the straight distance to the target, once per node
    double& d = h_[static_cast<std::size_t>(v)];
    if (d < 0.0) d = (points_[v] - target).norm();
    return d;
  };
  auto relax = [&](int from_arc, int a, double c) {
    if (c >= g_[static_cast<std::size_t>(a)]) return;
    if (dominated(arcs_[static_cast<std::size_t>(a)].to, arcs_[static_cast<std::size_t>(a)].heading, c)) return;
    g_[static_cast<std::size_t>(a)] = c;
    parent_[static_cast<std::size_t>(a)] = from_arc;
    heap_.push({c + h(arcs_[static_cast<std::size_t>(a)].to), a});
  };
  auto grow = [&] {  // per-arc state for arcs built since the last call
    g_.resize(arcs_.size(), std::numeric_limits<double>::infinity());
    parent_.resize(arcs_.size(), -1);
    closed_.resize(arcs_.size(), 0);
    in_next_.resize(arcs_.size(), -1);
  };
  grow();
  for (int a = arcs_begin_[s]; a < arcs_end_[s]; ++a) relax(-1, a, arcs_[static_cast<std::size_t>(a)].cost);
  int goal_arc = -1;
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
    ++route.expanded;
    if (v == t) {
      goal_arc = a;
      break;
    }
    if (arcs_begin_[v] < 0) {
      build_arcs(clusters, memory, blocked_now, v, verified, more_neighbours);
      grow();
    }
    const double gv = g_[ua];
    const double in = arcs_[ua].heading;
    for (int b = arcs_begin_[v]; b < arcs_end_[v]; ++b) {
      const Arc& out = arcs_[static_cast<std::size_t>(b)];
      relax(a, b, gv + out.cost + settings_.turn_weight * turn_angle(in, out.heading));
    }
  }
  if (goal_arc < 0) return route;
  route.cost = g_[static_cast<std::size_t>(goal_arc)];
  scratch_.clear();
  for (int a = goal_arc; a >= 0; a = parent_[static_cast<std::size_t>(a)]) scratch_.push_back(arcs_[static_cast<std::size_t>(a)].to);
  scratch_.push_back(s);
  std::reverse(scratch_.begin(), scratch_.end());
  for (int v : scratch_) {
    route.nodes.push_back(v == s ? Route::kStart : v == t ? Route::kTarget : ids_[v]);
    route.points.push_back(points_[v]);
  }
  return route;
}

}  // namespace amp::nav
