#include "amp/nav/pgcs/route_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amp/learn/pgcs.hpp"

namespace amp::nav {

RouteGraph::RouteGraph(const learn::Pgcs& clusters, const EdgeMemory& memory, const EdgeMemory* blocked_now)
    : clusters_(clusters), memory_(memory), blocked_now_(blocked_now) {}

RouteGraph::~RouteGraph() = default;

std::uint64_t RouteGraph::revision() const { return static_cast<std::uint64_t>(clusters_.steps()); }

void RouteGraph::refresh() {
  const std::vector<int>& alive = clusters_.ids();
  const std::uint64_t now = revision();
  if (fresh_ && now == revision_ && ids_.size() == alive.size()) return;
  // A new graph: its clusters' local indices, points, prior excesses and neighbours afresh.
  fresh_ = true;
  revision_ = now;
  const int k = static_cast<int>(alive.size());
  ids_.assign(alive.begin(), alive.end());
  const int max_id = alive.empty() ? 0 : alive.back();
  local_of_.assign(static_cast<std::size_t>(max_id) + 1, -1);
  points_.resize(static_cast<std::size_t>(k));
  double prior_sum = 0.0;
  for (int i = 0; i < k; ++i) {
    local_of_[static_cast<std::size_t>(ids_[i])] = i;
    points_[i] = point(ids_[i]);
    prior_sum += clusters_.prior(ids_[i]);
  }
  log_mean_prior_ = k > 0 && prior_sum > 0.0 ? std::log(prior_sum / k) : 0.0;
  // Prior excesses are taken when a node is first reached.
  excess_.assign(static_cast<std::size_t>(k), std::nan(""));
  nbr_begin_.assign(static_cast<std::size_t>(k), -1);
  nbr_end_.assign(static_cast<std::size_t>(k), -1);
  nbrs_.clear();
}

int RouteGraph::local(int id) const {
  return id >= 0 && static_cast<std::size_t>(id) < local_of_.size() ? local_of_[static_cast<std::size_t>(id)] : -1;
}

double RouteGraph::take_prior_excess(int v) {
  const double pi = clusters_.prior(ids_[v]);
  double& e = excess_[static_cast<std::size_t>(v)];
  e = pi > 0.0 ? std::max(0.0, log_mean_prior_ - std::log(pi)) : std::numeric_limits<double>::infinity();
  return e;
}

void RouteGraph::find_neighbours(int v) {
  nbr_begin_[v] = static_cast<int>(nbrs_.size());
  clusters_.triangulation().neighbours(ids_[v], scratch_);
  more_neighbours(ids_[v], scratch_);
  for (int id : scratch_) {
    const int w = local(id);
    if (w < 0 || !std::isfinite(points_[w].x())) continue;
    if (std::any_of(nbrs_.begin() + nbr_begin_[v], nbrs_.end(), [&](const Neighbour& n) { return n.to == w; })) continue;
    const Eigen::Vector2d d = points_[w] - points_[v];
    const double length = d.norm();
    nbrs_.push_back({w, length, length > 0.0 ? std::atan2(d.y(), d.x()) : std::nan(""), verified(ids_[v], id)});
  }
  nbr_end_[v] = static_cast<int>(nbrs_.size());
}

Eigen::Vector2d CentreGraph::point(int k) const { return clusters().mean(k); }

}  // namespace amp::nav
