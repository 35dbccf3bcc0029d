#include "amp/nav/pgcs/portal_graph.hpp"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "amp/nav/pgcs/edge_memory.hpp"
#include "nav/pgcs/exploring.hpp"

namespace amp::nav {
namespace {

using pgcs_test::Exploring;

TEST(PortalGraph, EdgesWithAPortalAreVerifiedAndCrossedPairsJoined) {
  Exploring e(4);
  e.explore(5000);
  e.explorer.adopt_exemplars();
  const EdgeMemory memory(0.05);
  PortalGraph g(e.explorer, memory);
  g.refresh();
  int verified = 0;
  for (int v = 0; v < g.size(); ++v) {
    const int a = g.id(v);
    std::vector<int> found;
    for (const RouteGraph::Neighbour& n : g.neighbours(v)) {
      EXPECT_EQ(n.verified, e.explorer.portal(a, g.id(n.to)) != nullptr);
      verified += n.verified ? 1 : 0;
      found.push_back(g.id(n.to));
      EXPECT_EQ(g.at(n.to), e.explorer.node_point(g.id(n.to)));
    }
    if (!g.at(v).allFinite()) continue;
    for (int b : e.explorer.portals().crossed(a)) {
      if (e.explorer.portal(a, b) != nullptr && g.local(b) >= 0 && g.at(g.local(b)).allFinite()) {
        EXPECT_NE(std::find(found.begin(), found.end(), b), found.end());
      }
    }
  }
  EXPECT_GT(verified, 0);
}

TEST(PortalGraph, FollowsTheExplorer) {
  Exploring e(4);
  e.explore(5000);
  e.explorer.adopt_exemplars();
  const EdgeMemory memory(0.05);
  PortalGraph g(e.explorer, memory);
  g.refresh();
  int a = -1, b = -1;
  for (int v = 0; v < g.size() && a < 0; ++v) {
    for (const RouteGraph::Neighbour& n : g.neighbours(v)) {
      if (n.verified) a = g.id(v), b = g.id(n.to);
    }
  }
  ASSERT_GE(a, 0);
  e.explorer.drop_portal(a, b);
  g.refresh();
  for (const RouteGraph::Neighbour& n : g.neighbours(g.local(a))) {
    if (g.id(n.to) == b) {
      EXPECT_FALSE(n.verified);
    }
  }
}

}  // namespace
}  // namespace amp::nav
