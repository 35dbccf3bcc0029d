#include "amp/nav/pgcs/route_graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "amp/learn/pgcs.hpp"
#include "amp/nav/pgcs/edge_memory.hpp"
#include "amp/nav/pgcs/route_planner.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

// A(0,0) B(1,0) C(2,0) on a line and D(1,1) above: Delaunay edges AB, BC, AD, BD, CD.
struct Diamond {
  learn::Pgcs g;
  int a, b, c, d;
  Diamond() {
    a = g.add_cluster({0, 0}, 0.1, 0.4);
    b = g.add_cluster({1, 0}, 0.1, 0.1);
    c = g.add_cluster({2, 0}, 0.1, 0.25);
    d = g.add_cluster({1, 1}, 0.1, 0.25);
  }
};

std::vector<int> ids_of(RouteGraph& graph, int v) {
  std::vector<int> out;
  for (const RouteGraph::Neighbour& n : graph.neighbours(v)) out.push_back(graph.id(n.to));
  std::sort(out.begin(), out.end());
  return out;
}

// A graph whose points the test moves, an extra edge A-C, and A-B the only verified edge; it says
// it changed only when told to.
class TestGraph final : public RouteGraph {
 public:
  TestGraph(const Diamond& w, const EdgeMemory& memory) : RouteGraph(w.g, memory), w_(w) {}
  V shift = V::Zero();
  bool leave_out_d = false;
  std::uint64_t rev = 0;

 protected:
  V point(int k) const override {
    if (leave_out_d && k == w_.d) return V::Constant(std::nan(""));
    return clusters().mean(k) + shift;
  }
  bool verified(int a, int b) const override { return std::min(a, b) == w_.a && std::max(a, b) == w_.b; }
  void more_neighbours(int k, std::vector<int>& out) const override {
    if (k == w_.a) out.push_back(w_.c);
    if (k == w_.c) out.insert(out.end(), {w_.a, w_.b});  // B twice: kept once
  }
  std::uint64_t revision() const override { return rev; }

 private:
  const Diamond& w_;
};

TEST(RouteGraph, CentreGraphIsTheDelaunayGraphOfTheCentresEveryEdgeVerified) {
  Diamond w;
  const EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  graph.refresh();
  ASSERT_EQ(graph.size(), 4);
  for (int v = 0; v < graph.size(); ++v) {
    EXPECT_EQ(graph.id(v), w.g.ids()[static_cast<std::size_t>(v)]);
    EXPECT_EQ(graph.local(graph.id(v)), v);
    EXPECT_EQ(graph.at(v), w.g.mean(graph.id(v)));
    for (const RouteGraph::Neighbour& n : graph.neighbours(v)) {
      EXPECT_TRUE(n.verified);
      EXPECT_NEAR(n.length, (graph.at(n.to) - graph.at(v)).norm(), 1e-15);
    }
  }
  EXPECT_EQ(graph.local(99), -1);
  EXPECT_EQ(graph.local(-1), -1);
  EXPECT_EQ(ids_of(graph, graph.local(w.a)), (std::vector<int>{w.b, w.d}));
  EXPECT_EQ(ids_of(graph, graph.local(w.b)), (std::vector<int>{w.a, w.c, w.d}));
}

TEST(RouteGraph, PriorExcessIsTheLogOfMeanPriorOverPriorWhenPositive) {
  Diamond w;  // priors 0.4, 0.1, 0.25, 0.25: mean 0.25
  const EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  graph.refresh();
  EXPECT_EQ(graph.prior_excess(graph.local(w.a)), 0.0);
  EXPECT_NEAR(graph.prior_excess(graph.local(w.b)), std::log(2.5), 1e-12);
  EXPECT_NEAR(graph.prior_excess(graph.local(w.c)), 0.0, 1e-12);
  learn::Pgcs unvisited;
  unvisited.add_cluster({0, 0}, 0.1, 1.0);
  unvisited.add_cluster({1, 0}, 0.1, 0.0);
  CentreGraph other(unvisited, memory);
  other.refresh();
  EXPECT_EQ(other.prior_excess(1), std::numeric_limits<double>::infinity());
}

TEST(RouteGraph, MoreNeighboursJoinOnceAndOnlyTheImplementationsEdgesAreVerified) {
  Diamond w;
  const EdgeMemory memory(0.01);
  TestGraph graph(w, memory);
  graph.refresh();
  EXPECT_EQ(ids_of(graph, graph.local(w.a)), (std::vector<int>{w.b, w.c, w.d}));
  EXPECT_EQ(ids_of(graph, graph.local(w.c)), (std::vector<int>{w.a, w.b, w.d}));
  for (const RouteGraph::Neighbour& n : graph.neighbours(graph.local(w.a))) {
    EXPECT_EQ(n.verified, graph.id(n.to) == w.b);
  }
}

TEST(RouteGraph, TheCacheHoldsUntilTheRevisionChanges) {
  Diamond w;
  const EdgeMemory memory(0.01);
  TestGraph graph(w, memory);
  graph.refresh();
  const int a = graph.local(w.a), d = graph.local(w.d);
  graph.shift = V(10, 0);
  graph.leave_out_d = true;
  graph.refresh();  // the same revision: the points and neighbours found before
  EXPECT_EQ(graph.at(a), V(0, 0));
  EXPECT_EQ(ids_of(graph, a), (std::vector<int>{w.b, w.c, w.d}));
  ++graph.rev;
  graph.refresh();
  EXPECT_EQ(graph.at(a), V(10, 0));
  EXPECT_FALSE(std::isfinite(graph.at(d).x()));
  EXPECT_EQ(ids_of(graph, a), (std::vector<int>{w.b, w.c}));  // D is left out
}

TEST(RouteGraph, ANewClusterIsSeenWithoutANewRevision) {
  Diamond w;
  const EdgeMemory memory(0.01);
  TestGraph graph(w, memory);
  graph.refresh();
  const int e = w.g.add_cluster({1, -1}, 0.1, 0.25);
  graph.refresh();
  ASSERT_EQ(graph.size(), 5);
  EXPECT_GE(graph.local(e), 0);
  const std::vector<int> b = ids_of(graph, graph.local(w.b));
  EXPECT_NE(std::find(b.begin(), b.end(), e), b.end());
}

TEST(RouteGraph, PlansOnAKeptGraphSeeTheMemoryAsItIsNow) {
  Diamond w;
  EdgeMemory memory(0.01);
  CentreGraph graph(w.g, memory);
  RoutePlanner p({1.0, 0.0, 1});
  const V start(-0.5, 0), target(2.5, 0);
  EXPECT_EQ(p.plan(graph, start, target).nodes, (std::vector<int>{Route::kStart, w.a, w.b, w.c, Route::kTarget}));
  memory.mark(w.a, w.b, w.g.mean(w.a), w.g.mean(w.b));
  EXPECT_EQ(p.plan(graph, start, target).nodes, (std::vector<int>{Route::kStart, w.a, w.d, w.c, Route::kTarget}));
}

}  // namespace
}  // namespace amp::nav
