#include "amp/roadmap/prm/lifelong_astar.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/prm/astar.hpp"

namespace amp::roadmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

State p2(double x, double y) { return (State(2) << x, y).finished(); }

// Bellman-Ford from s: an independent reference for shortest distances.
std::vector<double> reference_costs(const Roadmap& g, VertexId s) {
  std::vector<double> d(g.vertex_count(), kInf);
  d[s] = 0.0;
  for (std::size_t it = 0; it < g.vertex_count(); ++it) {
    for (VertexId v = 0; v < g.vertex_count(); ++v) {
      for (const Edge& e : g.edges(v)) d[e.to] = std::min(d[e.to], d[v] + e.cost);
    }
  }
  return d;
}

double path_cost(const Roadmap& g, const std::vector<VertexId>& path) {
  double cost = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_TRUE(g.has_edge(path[i - 1], path[i]));
    for (const Edge& e : g.edges(path[i - 1])) {
      if (e.to == path[i]) cost += e.cost;
    }
  }
  return cost;
}

// A roadmap that a test changes as Lazy PRM does (a vertex joined to its nearest older ones, edges
// removed), telling the search about each change. Vertices 0 and 1 sit in opposite corners, not
// joined directly.
struct ChangingRoadmap {
  const core::Space& space;
  Roadmap g;
  LifelongAStar& search;
  void add_vertex_with_edges(core::Rng& rng, std::size_t edges) {
    const State q = g.vertex_count() == 0   ? p2(0.5, 0.5)
                    : g.vertex_count() == 1 ? p2(9.5, 9.5)
                                            : p2(rng.uniform(0, 10), rng.uniform(0, 10));
    const VertexId v = g.add_vertex(q);
    search.touch(v);
    std::vector<std::pair<double, VertexId>> older;
    for (VertexId u = 0; u < v && v > 1; ++u) older.emplace_back(space.distance(g.state(u), q), u);
    std::sort(older.begin(), older.end());
    for (std::size_t i = 0; i < std::min(edges, older.size()); ++i) {
      g.add_edge(older[i].second, v, older[i].first);
      search.touch(older[i].second);
    }
  }
  // Removes a random edge of `path` (as Lazy PRM removes the edges of a candidate path that fail).
  void remove_path_edge(core::Rng& rng, const std::vector<VertexId>& path) {
    if (path.size() < 2) return;
    const std::size_t i = rng.uniform_index(path.size() - 1);
    g.remove_edge(path[i], path[i + 1]);
    search.touch(path[i]);
    search.touch(path[i + 1]);
  }
  void remove_random_edge(core::Rng& rng) {
    const VertexId v = rng.uniform_index(g.vertex_count());
    if (g.edges(v).empty()) return;
    const VertexId u = g.edges(v)[rng.uniform_index(g.edges(v).size())].to;
    g.remove_edge(u, v);
    search.touch(u);
    search.touch(v);
  }
};

TEST(LifelongAStar, ShortestPathByHandAndNoneWhenCut) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap g;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 3.0}, {2.0, 0.0}, {4.0, 0.0}}) g.add_vertex(p2(x, y));
  auto connect = [&](VertexId a, VertexId b) { g.add_edge(a, b, space.distance(g.state(a), g.state(b))); };
  connect(0, 1);
  connect(1, 3);
  connect(0, 2);
  connect(2, 3);
  LifelongAStar search(0, 3);
  std::vector<VertexId> path;
  ASSERT_TRUE(search.search(g, space, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0, 2, 3}));  // length 4 against 2 sqrt(10)
  g.remove_edge(2, 3);
  search.touch(2);
  search.touch(3);
  ASSERT_TRUE(search.search(g, space, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0, 1, 3}));
  g.remove_edge(0, 1);
  search.touch(0);
  search.touch(1);
  EXPECT_FALSE(search.search(g, space, path));
  EXPECT_TRUE(path.empty());
}

TEST(LifelongAStar, EqualCostTiesGoThroughTheLowerIdAsAStar) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap g;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 1.0}, {1.0, -1.0}, {2.0, 0.0}}) g.add_vertex(p2(x, y));
  for (const auto& [a, b] : {std::pair<VertexId, VertexId>{0, 2}, {2, 3}, {0, 1}, {1, 3}}) {
    g.add_edge(a, b, space.distance(g.state(a), g.state(b)));
  }
  LifelongAStar search(0, 3);
  std::vector<VertexId> path;
  ASSERT_TRUE(search.search(g, space, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0, 1, 3}));
}

TEST(LifelongAStar, StartIsGoal) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap g;
  g.add_vertex(p2(1, 1));
  LifelongAStar search(0, 0);
  std::vector<VertexId> path;
  ASSERT_TRUE(search.search(g, space, path));
  EXPECT_EQ(path, (std::vector<VertexId>{0}));
}

// Through hundreds of additions and removals (a quarter of them on the last path found), every
// repaired search finds a path exactly when one exists, of the reference's length, and the repairs
// expand far fewer vertices than searching anew each time.
TEST(LifelongAStar, RepairedSearchesStayShortestThroughChanges) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  core::Rng rng(7);
  LifelongAStar search(0, 1);
  ChangingRoadmap world{space, {}, search};
  for (int i = 0; i < 60; ++i) world.add_vertex_with_edges(rng, 3);
  std::vector<VertexId> path, fresh_path;
  std::size_t repaired = 0, fresh = 0, found_rounds = 0;
  for (int round = 0; round < 300; ++round) {
    if (round % 4 == 0) {
      world.remove_path_edge(rng, path);
    } else if (round % 4 == 1) {
      world.remove_random_edge(rng);
    } else {
      world.add_vertex_with_edges(rng, 3);
    }
    const std::vector<double> ref = reference_costs(world.g, 0);
    const bool found = search.search(world.g, space, path);
    ASSERT_EQ(found, ref[1] < kInf) << "round " << round;
    if (found) {
      ++found_rounds;
      EXPECT_EQ(path.front(), 0u);
      EXPECT_EQ(path.back(), 1u);
      EXPECT_NEAR(path_cost(world.g, path), ref[1], 1e-9) << "round " << round;
    }
    repaired += search.expanded();
    AStar astar;
    ASSERT_EQ(astar.search(world.g, space, 0, 1, fresh_path), found);
    fresh += astar.expanded();
  }
  EXPECT_GT(found_rounds, 150u);   // measured: 225 of 300 rounds have a path
  EXPECT_LT(repaired * 3, fresh);  // measured: 2,444 expansions against A*'s 13,574
}

// The same changes in the same order give the same paths.
TEST(LifelongAStar, SameChangesSamePaths) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  auto run = [&] {
    core::Rng rng(3);
    LifelongAStar search(0, 1);
    ChangingRoadmap world{space, {}, search};
    std::vector<std::vector<VertexId>> paths;
    std::vector<VertexId> path;
    for (int i = 0; i < 10; ++i) world.add_vertex_with_edges(rng, 2);
    for (int round = 0; round < 200; ++round) {
      if (round % 2 == 0) world.remove_random_edge(rng);
      world.add_vertex_with_edges(rng, 4);
      search.search(world.g, space, path);
      paths.push_back(path);
    }
    return paths;
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace amp::roadmap
