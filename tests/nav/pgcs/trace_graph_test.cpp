#include "amp/nav/pgcs/trace_graph.hpp"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "amp/nav/pgcs/edge_memory.hpp"
#include "nav/pgcs/exploring.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
using pgcs_test::Exploring;

std::vector<int> links_of(const TraceGraph& g, int k) {
  std::vector<int> out;
  g.append_links(k, out);
  return out;
}

TEST(TraceGraph, LinksAreSymmetricSortedAndTheVerifiedEdges) {
  Exploring e(4);
  e.explore(5000);
  e.explorer.adopt_exemplars();
  const EdgeMemory memory(0.05);
  TraceGraph g(e.explorer, e.corridor, memory);
  g.link();
  int linked = 0;
  for (int a : e.explorer.clusters().ids()) {
    const std::vector<int> l = links_of(g, a);
    EXPECT_TRUE(std::is_sorted(l.begin(), l.end()));
    EXPECT_EQ(std::adjacent_find(l.begin(), l.end()), l.end());
    for (int b : l) {
      EXPECT_TRUE(g.linked(b, a));
      ++linked;
    }
  }
  EXPECT_GT(linked, 0);
  g.refresh();
  for (int v = 0; v < g.size(); ++v) {
    std::vector<int> found;
    for (const RouteGraph::Neighbour& n : g.neighbours(v)) {
      EXPECT_EQ(n.verified, g.linked(g.id(v), g.id(n.to)));
      found.push_back(g.id(n.to));
    }
    // Every link to a cluster with a point is an edge, Delaunay neighbours or not.
    for (int b : links_of(g, g.id(v))) {
      if (g.local(b) >= 0 && g.at(g.local(b)).allFinite() && g.at(v).allFinite()) {
        EXPECT_NE(std::find(found.begin(), found.end(), b), found.end());
      }
    }
  }
  EXPECT_TRUE(links_of(g, -1).empty());
  EXPECT_FALSE(g.linked(-1, 0));
}

TEST(TraceGraph, LinksHoldUntilLinkedAgain) {
  Exploring e(6);
  e.explore(2000);
  const EdgeMemory memory(0.05);
  TraceGraph g(e.explorer, e.corridor, memory);
  g.link();
  std::vector<std::vector<int>> before;
  for (int k : e.explorer.clusters().ids()) before.push_back(links_of(g, k));
  e.corridor.forget(V(2.0, 1.0), 5.0);  // the whole trace
  std::size_t i = 0;
  for (int k : e.explorer.clusters().ids()) EXPECT_EQ(links_of(g, k), before[i++]);
  g.link();
  for (int k : e.explorer.clusters().ids()) EXPECT_TRUE(links_of(g, k).empty());
}

TEST(TraceGraph, CellsAreLabelledByTheirNearestCentre) {
  Exploring e(8);
  e.explore(3000);
  e.explorer.adopt_exemplars();
  const EdgeMemory memory(0.05);
  TraceGraph g(e.explorer, e.corridor, memory);
  const FreeMask& raster = e.corridor.geometry();
  for (int cell = 0; cell < static_cast<int>(raster.cell_count()); cell += 37) {
    EXPECT_EQ(g.cell_label(cell), e.explorer.clusters().triangulation().nearest(raster.cell_center(cell)));
  }
  EXPECT_EQ(g.cell_label(-1), -1);
  const V p = e.sim.state().position;
  const int home = g.home(p);
  if (home >= 0) {
    EXPECT_EQ(home, g.cell_label(raster.cell_of(p)));
    EXPECT_TRUE(e.explorer.node_point(home).allFinite());
  }
}

}  // namespace
}  // namespace amp::nav
