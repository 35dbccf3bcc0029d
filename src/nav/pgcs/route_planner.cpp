#include "amp/nav/pgcs/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "amp/core/error.hpp"
#include "amp/learn/pgcs.hpp"

namespace amp::nav {

namespace {
// Turning angle in [0, pi] between the directions a and b; 0 when either is a null vector.
double turn_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) return 0.0;
  return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
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

Route RoutePlanner::plan(const learn::Pgcs& clusters, const EdgeMemory& memory, const Eigen::Vector2d& start,
                         const Eigen::Vector2d& target, std::span<const FailedAttachment> failed,
                         double failed_tolerance) {
  Route route;
  const std::vector<int>& alive = clusters.ids();
  const int k = static_cast<int>(alive.size());
  const int s = k, t = k + 1, n = k + 2;
  ids_.assign(alive.begin(), alive.end());
  const int max_id = alive.empty() ? 0 : alive.back();
  local_of_.assign(static_cast<std::size_t>(max_id) + 1, -1);
  points_.resize(static_cast<std::size_t>(n));
  penalty_.assign(static_cast<std::size_t>(n), 0.0);
  double prior_sum = 0.0;
  for (int i = 0; i < k; ++i) {
    local_of_[static_cast<std::size_t>(ids_[i])] = i;
    points_[i] = clusters.mean(ids_[i]);
    prior_sum += clusters.prior(ids_[i]);
  }
  points_[s] = start;
  points_[t] = target;
  if (settings_.prior_weight > 0.0 && k > 0) {
    const double mean_prior = prior_sum / k;
    for (int i = 0; i < k; ++i) {
      const double pi = clusters.prior(ids_[i]);
      penalty_[i] = pi > 0.0 ? settings_.prior_weight * std::max(0.0, std::log(mean_prior / pi))
                             : std::numeric_limits<double>::max() / 4;  // never visited: last resort
    }
  }
  nearest_centres(clusters, start, failed, failed_tolerance, start_links_);
  nearest_centres(clusters, target, failed, failed_tolerance, target_links_);
  // Straight from start to target only when the target is nearer than every centre the start joins.
  const double direct2 = (target - start).squaredNorm();
  const bool direct_failed = std::any_of(failed.begin(), failed.end(), [&](const FailedAttachment& f) {
    return f.cluster == Route::kTarget && (f.point - start).squaredNorm() <= failed_tolerance * failed_tolerance;
  });
  const bool direct = !direct_failed && (start_links_.empty() ||
                                         direct2 <= (points_[start_links_.front()] - start).squaredNorm());

  const std::size_t states = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (g_.size() < states) {
    g_.resize(states);
    parent_.resize(states);
    stamp_.assign(states, 0);
    closed_.assign(states, 0);
  }
  if (++generation_ == 0) {  // wrapped: stale stamps could read as current
    std::fill(stamp_.begin(), stamp_.end(), 0);
    std::fill(closed_.begin(), closed_.end(), 0);
    generation_ = 1;
  }
  const std::uint32_t gen = generation_;
  heap_.clear();
  const std::greater<std::pair<double, int>> later;
  auto h = [&](int v) { return (points_[v] - target).norm(); };
  auto relax = [&](int from_state, int u, int v, int w, double g_v) {
    const std::size_t st = static_cast<std::size_t>(v) * n + static_cast<std::size_t>(w);
    double c = g_v + (points_[w] - points_[v]).norm() + penalty_[w];
    if (u != v) c += settings_.turn_weight * turn_angle(points_[v] - points_[u], points_[w] - points_[v]);
    if (stamp_[st] == gen && c >= g_[st]) return;
    stamp_[st] = gen;
    g_[st] = c;
    parent_[st] = from_state;
    heap_.emplace_back(c + h(w), static_cast<int>(st));
    std::push_heap(heap_.begin(), heap_.end(), later);
  };
  // The start state is (s, s): at the start with no incoming edge.
  const int start_state = s * n + s;
  stamp_[static_cast<std::size_t>(start_state)] = gen;
  g_[static_cast<std::size_t>(start_state)] = 0.0;
  parent_[static_cast<std::size_t>(start_state)] = -1;
  heap_.emplace_back(h(s), start_state);
  int goal_state = -1;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const int st = heap_.back().second;
    heap_.pop_back();
    const auto ust = static_cast<std::size_t>(st);
    if (closed_[ust] == gen) continue;
    closed_[ust] = gen;
    ++route.expanded;
    const int u = st / n, v = st % n;
    if (v == t) {
      goal_state = st;
      break;
    }
    const double gv = g_[ust];
    if (v == s) {
      for (int w : start_links_) relax(st, u, v, w, gv);
      if (direct) relax(st, u, v, t, gv);
      continue;
    }
    clusters.triangulation().neighbours(ids_[v], neighbours_);
    for (int id : neighbours_) {
      const int w = local_of_[static_cast<std::size_t>(id)];
      if (memory.illegal(ids_[v], id, points_[v], points_[w])) continue;
      relax(st, u, v, w, gv);
    }
    if (std::find(target_links_.begin(), target_links_.end(), v) != target_links_.end()) relax(st, u, v, t, gv);
  }
  if (goal_state < 0) return route;
  route.cost = g_[static_cast<std::size_t>(goal_state)];
  scratch_.clear();
  for (int st = goal_state; st >= 0; st = parent_[static_cast<std::size_t>(st)]) scratch_.push_back(st % n);
  std::reverse(scratch_.begin(), scratch_.end());
  for (int v : scratch_) {
    route.nodes.push_back(v == s ? Route::kStart : v == t ? Route::kTarget : ids_[v]);
    route.points.push_back(points_[v]);
  }
  return route;
}

}  // namespace amp::nav
