#include "amp/roadmap/prm/astar.hpp"

#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"

namespace amp::roadmap {
namespace {

State p2(double x, double y) { return (State(2) << x, y).finished(); }

void connect(Roadmap& g, const core::Space& s, VertexId a, VertexId b) {
  g.add_edge(a, b, s.distance(g.state(a), g.state(b)));
}

TEST(AStar, ShortestPathByHand) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap g;
  // 0 (0,0) - 1 (1,3) - 3 (4,0): length 2*sqrt(10) = 6.32; 0 - 2 (2,0) - 3: length 4 (shorter).
  g.add_vertex(p2(0, 0));
  g.add_vertex(p2(1, 3));
  g.add_vertex(p2(2, 0));
  g.add_vertex(p2(4, 0));
  g.add_vertex(p2(9, 9));  // unreachable
  connect(g, space, 0, 1);
  connect(g, space, 1, 3);
  connect(g, space, 0, 2);
  connect(g, space, 2, 3);
  AStar astar;
  std::vector<VertexId> path;
  ASSERT_TRUE(astar.search(g, space, 0, 3, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0, 2, 3}));
  EXPECT_FALSE(astar.search(g, space, 0, 4, path));
  EXPECT_TRUE(path.empty());
  ASSERT_TRUE(astar.search(g, space, 3, 3, path));
  EXPECT_EQ(path, (std::vector<VertexId>{3}));
}

TEST(AStar, EqualCostTiesGoThroughTheLowerId) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap g;
  g.add_vertex(p2(0, 0));
  g.add_vertex(p2(1, 1));   // 1 and 2: two mirror-image routes of equal length
  g.add_vertex(p2(1, -1));
  g.add_vertex(p2(2, 0));
  connect(g, space, 0, 2);  // insertion order favours 2; the tie-break must still pick 1
  connect(g, space, 2, 3);
  connect(g, space, 0, 1);
  connect(g, space, 1, 3);
  AStar astar;
  std::vector<VertexId> path;
  ASSERT_TRUE(astar.search(g, space, 0, 3, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0, 1, 3}));
}

// Dijkstra by repeated relaxation (Bellman-Ford), as an independent reference.
std::vector<double> reference_costs(const Roadmap& g, VertexId s) {
  std::vector<double> d(g.vertex_count(), std::numeric_limits<double>::infinity());
  d[s] = 0.0;
  for (std::size_t it = 0; it < g.vertex_count(); ++it) {
    for (VertexId v = 0; v < g.vertex_count(); ++v) {
      for (const Edge& e : g.edges(v)) d[e.to] = std::min(d[e.to], d[v] + e.cost);
    }
  }
  return d;
}

TEST(AStar, OptimalOnRandomGraphs) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  core::Rng rng(11);
  Roadmap g;
  for (int i = 0; i < 120; ++i) g.add_vertex(p2(rng.uniform(0, 10), rng.uniform(0, 10)));
  for (int i = 0; i < 300; ++i) {
    const VertexId a = rng.uniform_index(120), b = rng.uniform_index(120);
    if (a != b && !g.has_edge(a, b)) connect(g, space, a, b);
  }
  const std::vector<double> ref = reference_costs(g, 0);
  AStar astar;
  std::vector<VertexId> path;
  for (VertexId goal = 1; goal < 120; ++goal) {
    const bool found = astar.search(g, space, 0, goal, path);
    ASSERT_EQ(found, ref[goal] < std::numeric_limits<double>::infinity());
    if (!found) continue;
    double cost = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
      ASSERT_TRUE(g.has_edge(path[i - 1], path[i]));
      cost += space.distance(g.state(path[i - 1]), g.state(path[i]));
    }
    EXPECT_NEAR(cost, ref[goal], 1e-9);
  }
}

}  // namespace
}  // namespace amp::roadmap
