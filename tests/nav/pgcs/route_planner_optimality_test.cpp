// RoutePlanner's search prunes dominated arrivals, and a RouteGraph keeps its nodes' neighbours
// across plans while it stands still: on random graphs, its route costs what an independent
// Dijkstra over (previous node, node) states finds optimal, and a plan on a kept graph equals the
// plan on a new one, also after the remembered illegal edges changed between them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"
#include "amp/learn/pgcs.hpp"
#include "amp/nav/pgcs/route_planner.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

struct RandomGraph {
  learn::Pgcs g;
  std::vector<int> ids;
  V start, target;
  explicit RandomGraph(std::uint64_t seed) {
    core::Rng rng(seed);
    for (int i = 0; i < 40; ++i) {
      ids.push_back(g.add_cluster({rng.uniform(0.0, 10.0), rng.uniform(0.0, 10.0)}, 0.1, rng.uniform(0.01, 1.0)));
    }
    start = {rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)};
    target = {rng.uniform(9.0, 10.0), rng.uniform(9.0, 10.0)};
  }
};

// Verified: a fixed pseudo-random half of the pairs.
bool half_verified(int a, int b) { return ((std::min(a, b) * 31 + std::max(a, b) * 17) % 2) == 0; }

// The centres' Delaunay graph with the verified half above.
class HalfVerifiedGraph final : public RouteGraph {
 public:
  using RouteGraph::RouteGraph;

 protected:
  Eigen::Vector2d point(int k) const override { return clusters().mean(k); }
  bool verified(int a, int b) const override { return half_verified(a, b); }
  void more_neighbours(int, std::vector<int>&) const override {}
};

double heading(const V& from, const V& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }
double turn(double a, double b) {
  const double d = std::abs(b - a);
  return d > std::numbers::pi ? 2.0 * std::numbers::pi - d : d;
}

// The optimal cost under RoutePlanner's model, by Dijkstra over states (previous node, node); the
// start is node -1, the target -2 (the test's points keep the target farther than every centre).
double brute_force(const RandomGraph& w, const RouteSettings& s, const EdgeMemory& memory) {
  const auto nearest = [&](const V& p) {
    std::vector<std::pair<double, int>> by;
    for (int id : w.ids) by.emplace_back((w.g.mean(id) - p).squaredNorm(), id);
    std::sort(by.begin(), by.end());
    std::vector<int> out;
    for (int i = 0; i < s.attach; ++i) out.push_back(by[static_cast<std::size_t>(i)].second);
    return out;
  };
  const std::vector<int> from_start = nearest(w.start), to_target = nearest(w.target);
  double prior_sum = 0.0;
  for (int id : w.ids) prior_sum += w.g.prior(id);
  const double log_mean = std::log(prior_sum / static_cast<double>(w.ids.size()));
  const auto point = [&](int v) { return v == -1 ? w.start : v == -2 ? w.target : V(w.g.mean(v)); };
  const auto penalty = [&](int v) { return v < 0 ? 0.0 : s.prior_weight * std::max(0.0, log_mean - std::log(w.g.prior(v))); };
  const auto out_of = [&](int v) {
    std::vector<std::pair<int, double>> out;  // (to, length factor)
    if (v == -1) {
      for (int k : from_start) out.emplace_back(k, 1.0 + s.unverified_weight);
      return out;
    }
    std::vector<int> n;
    w.g.triangulation().neighbours(v, n);
    for (int k : n) {
      if (memory.illegal(v, k, w.g.mean(v), w.g.mean(k))) continue;
      out.emplace_back(k, half_verified(v, k) ? 1.0 : 1.0 + s.unverified_weight);
    }
    if (std::find(to_target.begin(), to_target.end(), v) != to_target.end()) out.emplace_back(-2, 1.0);
    return out;
  };
  using State = std::tuple<double, int, int>;  // cost, previous, node
  std::priority_queue<State, std::vector<State>, std::greater<>> open;
  std::map<std::pair<int, int>, double> done;
  open.emplace(0.0, -3, -1);
  while (!open.empty()) {
    const auto [c, u, v] = open.top();
    open.pop();
    if (done.contains({u, v})) continue;
    done[{u, v}] = c;
    if (v == -2) return c;
    for (const auto& [k, factor] : out_of(v)) {
      const double turned = u == -3 ? 0.0 : turn(heading(point(u), point(v)), heading(point(v), point(k)));
      open.emplace(c + factor * (point(k) - point(v)).norm() + penalty(k) + s.turn_weight * turned, v, k);
    }
  }
  return std::numeric_limits<double>::infinity();
}

TEST(RoutePlannerOptimality, RouteCostsWhatDijkstraOverTurnStatesFinds) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const RandomGraph w(seed);
    core::Rng rng(seed + 100);
    const RouteSettings s{rng.uniform(0.0, 3.0), rng.uniform(0.0, 2.0), 2, rng.uniform(0.0, 2.0), 100.0};
    EdgeMemory memory(0.01);
    HalfVerifiedGraph graph(w.g, memory);
    const Route r = RoutePlanner(s).plan(graph, w.start, w.target);
    const double best = brute_force(w, s, memory);
    ASSERT_FALSE(r.empty()) << "seed " << seed;
    EXPECT_NEAR(r.cost, best, 1e-9 * std::max(1.0, best)) << "seed " << seed;
  }
}

TEST(RoutePlannerOptimality, KeptGraphPlansEqualFreshOnesAsEdgesTurnIllegal) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const RandomGraph w(seed);
    const RouteSettings s{1.0, 1.0, 2, 1.0, 100.0};
    RoutePlanner kept(s);
    EdgeMemory memory(0.01);
    HalfVerifiedGraph kept_graph(w.g, memory);
    for (int round = 0; round < 4; ++round) {
      const Route a = kept.plan(kept_graph, w.start, w.target);
      HalfVerifiedGraph fresh_graph(w.g, memory);
      const Route b = RoutePlanner(s).plan(fresh_graph, w.start, w.target);
      ASSERT_EQ(a.nodes, b.nodes) << "seed " << seed << " round " << round;
      EXPECT_DOUBLE_EQ(a.cost, b.cost);
      EXPECT_NEAR(a.cost, brute_force(w, s, memory), 1e-9 * std::max(1.0, a.cost));
      if (a.nodes.size() < 4) break;
      // The route's first edge between clusters turns illegal: the kept graph must not use it.
      memory.mark(a.nodes[1], a.nodes[2], w.g.mean(a.nodes[1]), w.g.mean(a.nodes[2]));
    }
  }
}

}  // namespace
}  // namespace amp::nav
