// neighbors/linear_neighbors.cpp: brute-force k nearest neighbours, the reference the KD-tree is
// tested against; here it is checked against a full sort itself, and against the KD-tree.
#include "amp/roadmap/neighbors/linear_neighbors.hpp"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"

namespace amp::roadmap {
namespace {

TEST(LinearNeighbors, SortedByDistanceThenIndex) {
  const core::JointSpace space = core::make_rn_space({0, 0}, {10, 10});
  LinearNeighbors nn(space);
  nn.add(5, (State(2) << 1, 0).finished());
  nn.add(2, (State(2) << 0, 1).finished());  // same distance as index 5: comes first
  nn.add(9, (State(2) << 3, 0).finished());
  nn.add(1, (State(2) << 0, 0.5).finished());
  std::vector<Neighbor> out;
  nn.k_nearest((State(2) << 0, 0).finished(), 3, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], (Neighbor{1, 0.5}));
  EXPECT_EQ(out[1], (Neighbor{2, 1.0}));
  EXPECT_EQ(out[2], (Neighbor{5, 1.0}));
}

// Every stored state's distance, sorted by (distance, index), first k: the definition.
std::vector<Neighbor> by_full_sort(const core::Space& space, const std::vector<std::pair<std::size_t, State>>& stored,
                                   const State& q, std::size_t k) {
  std::vector<Neighbor> all;
  for (const auto& [index, s] : stored) all.push_back(Neighbor{index, space.distance(q, s)});
  std::sort(all.begin(), all.end(), [](const Neighbor& a, const Neighbor& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
  all.resize(std::min(k, all.size()));
  return all;
}

TEST(LinearNeighbors, EqualsAFullSortOnRandomAndTiedPoints) {
  const core::JointSpace space = core::make_rn_space({0, 0, 0}, {4, 4, 4});
  for (const bool grid : {false, true}) {
    SCOPED_TRACE(grid ? "integer grid (ties)" : "uniform");
    core::Rng rng(grid ? 5 : 6);
    LinearNeighbors nn(space);
    std::vector<std::pair<std::size_t, State>> stored;
    auto draw = [&] {
      State s(3);
      for (int i = 0; i < 3; ++i) s[i] = grid ? static_cast<double>(rng.uniform_index(5)) : rng.uniform(0, 4);
      return s;
    };
    std::vector<Neighbor> got;
    for (std::size_t n = 0; n < 300; ++n) {
      const std::size_t index = 1000 - 3 * n;  // decreasing, sparse: order of insertion is not the tie-break
      const State s = draw();
      nn.add(index, s);
      stored.emplace_back(index, s);
      if (n % 23 == 0 || n == 299) {
        for (const std::size_t k : {1u, 4u, 17u, 400u}) {
          const State q = draw();
          nn.k_nearest(q, k, got);
          ASSERT_EQ(got, by_full_sort(space, stored, q, k)) << n + 1 << " states, k = " << k;
        }
      }
    }
    EXPECT_EQ(nn.size(), 300u);
  }
}

TEST(LinearNeighbors, EqualsKdTreeNeighborsOnRandomPoints) {
  const core::JointSpace space = core::make_se2_space(0, 0, 10, 5, 0.8);
  core::Rng rng(21);
  LinearNeighbors linear(space);
  KdTreeNeighbors tree(space);
  linear.reserve(500);
  std::vector<Neighbor> a, b;
  for (std::size_t i = 0; i < 500; ++i) {
    State s;
    space.sample_uniform(rng, s);
    linear.add(i, s);
    tree.add(i, s);
    if (i % 50 == 49) {
      for (const std::size_t k : {1u, 10u}) {
        State q;
        space.sample_uniform(rng, q);
        linear.k_nearest(q, k, a);
        tree.k_nearest(q, k, b);
        ASSERT_EQ(a, b) << i + 1 << " states, k = " << k;
      }
    }
  }
}

TEST(LinearNeighbors, EmptyOrZeroKGivesNothingAndEveryQueryIsCounted) {
  const core::JointSpace space = core::make_rn_space({0}, {1});
  core::Counters counters;
  LinearNeighbors nn(space, &counters);
  std::vector<Neighbor> out{{3, 1.0}};
  nn.k_nearest((State(1) << 0.5).finished(), 3, out);
  EXPECT_TRUE(out.empty());
  nn.add(7, (State(1) << 0.25).finished());
  nn.k_nearest((State(1) << 0.5).finished(), 0, out);
  EXPECT_TRUE(out.empty());
  nn.k_nearest((State(1) << 0.5).finished(), 3, out);
  EXPECT_EQ(out, (std::vector<Neighbor>{{7, 0.25}}));
  EXPECT_EQ(counters.nn_queries(), 3u);
}

}  // namespace
}  // namespace amp::roadmap
