// prm/component_connection.cpp: ComponentNearestConnection's candidates, up to k nearest vertices
// of each connected component, nearest first over all of them.
#include "amp/roadmap/prm/component_connection.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/roadmap.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(ComponentNearestConnection, KNearestOfEachComponent) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap r;
  // Component A: x = 1, 2, 3, 4 on y = 0 (chained); B: x = 6, 7 on y = 0; C: the lone (5, 5).
  for (double x : {1.0, 2.0, 3.0, 4.0, 6.0, 7.0}) r.add_vertex(test::state2(x, 0));
  r.add_vertex(test::state2(5, 5));
  r.add_edge(0, 1, 1);
  r.add_edge(1, 2, 1);
  r.add_edge(2, 3, 1);
  r.add_edge(4, 5, 1);
  ComponentNearestConnection c(space, 2);
  for (VertexId v = 0; v < r.vertex_count(); ++v) c.add(v, r.state(v));
  const VertexId q = r.add_vertex(test::state2(5, 0));
  std::vector<Neighbor> out;
  c.candidates(r, q, out);
  std::vector<std::size_t> ids;
  for (const Neighbor& n : out) ids.push_back(n.index);
  // Nearest first: 4 (d 1, A), 3 (d 1, B), 2 (d 2, A), 5 (d 2, B), 6 (d 5, C); A's 1 and 0 dropped.
  EXPECT_EQ(ids, (std::vector<std::size_t>{3, 4, 2, 5, 6}));
  EXPECT_TRUE(std::is_sorted(out.begin(), out.end()));
}

// Random forests of chains against a recount: group the added vertices by component, keep each
// group's k nearest by (distance, id), merge and sort. The query vertex itself and vertices never
// added to the strategy are not candidates.
TEST(ComponentNearestConnection, EqualsAPerComponentRecountOnRandomForests) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  core::Rng rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE(trial);
    Roadmap r;
    const std::size_t k = 1 + rng.uniform_index(4);
    ComponentNearestConnection c(space, k);
    std::vector<VertexId> added;
    for (int i = 0; i < 60; ++i) {
      // Coordinates on a coarse grid, so that distance ties occur and are broken by id.
      const VertexId v = r.add_vertex(test::state2(static_cast<double>(rng.uniform_index(8)),
                                                   static_cast<double>(rng.uniform_index(8))));
      if (v > 0 && rng.uniform01() < 0.6) r.add_edge(v, rng.uniform_index(v), 1.0);
      if (rng.uniform01() < 0.9) {
        c.add(v, r.state(v));
        added.push_back(v);
      }
    }
    for (const VertexId q : {added.front(), added.back(), static_cast<VertexId>(r.vertex_count() - 1)}) {
      std::map<VertexId, std::vector<Neighbor>> groups;
      for (const VertexId u : added) {
        if (u != q) groups[r.component(u)].push_back(Neighbor{u, space.distance(r.state(q), r.state(u))});
      }
      std::vector<Neighbor> want;
      for (auto& [component, members] : groups) {
        std::sort(members.begin(), members.end());
        members.resize(std::min(k, members.size()));
        want.insert(want.end(), members.begin(), members.end());
      }
      std::sort(want.begin(), want.end());
      std::vector<Neighbor> got{{99, 9.0}};  // cleared first
      c.candidates(r, q, got);
      EXPECT_EQ(got, want) << "query " << q << ", k = " << k;
    }
  }
}

}  // namespace
}  // namespace amp::roadmap
