#include "amp/roadmap/roadmap.hpp"

#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"
#include "amp/roadmap/disjoint_sets.hpp"

namespace amp::roadmap {
namespace {

// Reference components by flood fill over an adjacency matrix.
std::vector<int> flood_labels(const std::vector<std::vector<bool>>& adj) {
  const std::size_t n = adj.size();
  std::vector<int> label(n, -1);
  int next = 0;
  for (std::size_t s = 0; s < n; ++s) {
    if (label[s] >= 0) continue;
    std::vector<std::size_t> stack{s};
    label[s] = next;
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      for (std::size_t w = 0; w < n; ++w) {
        if (adj[v][w] && label[w] < 0) {
          label[w] = next;
          stack.push_back(w);
        }
      }
    }
    ++next;
  }
  return label;
}

TEST(DisjointSets, MatchesFloodFill) {
  core::Rng rng(3);
  constexpr std::size_t kN = 200;
  DisjointSets sets;
  for (std::size_t i = 0; i < kN; ++i) EXPECT_EQ(sets.add(), i);
  std::vector<std::vector<bool>> adj(kN, std::vector<bool>(kN, false));
  for (int step = 0; step < 150; ++step) {
    const std::size_t a = rng.uniform_index(kN), b = rng.uniform_index(kN);
    const bool separate = !sets.same(a, b);
    EXPECT_EQ(sets.unite(a, b), separate);
    adj[a][b] = adj[b][a] = true;
  }
  const std::vector<int> label = flood_labels(adj);
  const int count = *std::max_element(label.begin(), label.end()) + 1;
  EXPECT_EQ(sets.set_count(), static_cast<std::size_t>(count));
  for (std::size_t a = 0; a < kN; ++a) {
    for (std::size_t b = 0; b < kN; ++b) ASSERT_EQ(sets.same(a, b), label[a] == label[b]);
  }
  sets.reset();
  EXPECT_EQ(sets.set_count(), kN);
  EXPECT_FALSE(sets.same(0, 1));
}

State point(double x) { return (State(1) << x).finished(); }

TEST(Roadmap, EdgesAndComponents) {
  Roadmap g;
  g.reserve(10, 4);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(g.add_vertex(point(i)), static_cast<VertexId>(i));
  EXPECT_EQ(g.component_count(), 6u);
  g.add_edge(0, 1, 1.0);
  g.add_edge(1, 2, 1.0);
  g.add_edge(3, 4, 1.0, EdgeCheck::kUnchecked);
  EXPECT_EQ(g.edge_count(), 3u);
  EXPECT_EQ(g.component_count(), 3u);  // {0,1,2} {3,4} {5}
  EXPECT_TRUE(g.same_component(0, 2));
  EXPECT_FALSE(g.same_component(2, 3));
  EXPECT_EQ(g.component(0), g.component(2));
  EXPECT_TRUE(g.has_edge(4, 3));
  EXPECT_EQ(g.edges(3).front().check, EdgeCheck::kUnchecked);
  g.mark_valid(4, 3);
  EXPECT_EQ(g.edges(3).front().check, EdgeCheck::kValid);
  EXPECT_EQ(g.edges(4).front().check, EdgeCheck::kValid);
  EXPECT_DOUBLE_EQ(g.state(4)[0], 4.0);
}

TEST(Roadmap, RemovingAnEdgeSplitsItsComponent) {
  Roadmap g;
  for (int i = 0; i < 4; ++i) g.add_vertex(point(i));
  g.add_edge(0, 1, 1.0);
  g.add_edge(1, 2, 1.0);
  g.add_edge(2, 3, 1.0);
  EXPECT_EQ(g.component_count(), 1u);
  EXPECT_TRUE(g.remove_edge(2, 1));
  EXPECT_FALSE(g.remove_edge(2, 1));
  EXPECT_EQ(g.edge_count(), 2u);
  EXPECT_FALSE(g.has_edge(1, 2));
  EXPECT_EQ(g.component_count(), 2u);
  EXPECT_FALSE(g.same_component(0, 3));
  // Edges and vertices added after a removal still join components.
  g.add_vertex(point(9));
  g.add_edge(1, 2, 1.0);
  g.add_edge(3, 4, 1.0);
  EXPECT_EQ(g.component_count(), 1u);
  EXPECT_TRUE(g.same_component(0, 4));
}

}  // namespace
}  // namespace amp::roadmap
