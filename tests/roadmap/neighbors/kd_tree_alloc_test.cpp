// The KD-tree's queries allocate nothing once the caller's output vector has its capacity (issue 36,
// item 4): k_nearest for k = 1 (RRT-Connect's nearest node) and k = 10 (a PRM's neighbours), and a
// fixed-radius search through DynamicKdTree's visitor, over a 7-D Panda-like joint space and the
// SE2 space of the neighbour tests. Insertion is amortised: its allocations grow with the number of
// doublings of the tree, not with the number of points. Global operator new, aligned forms
// included (the tree's boxes are cache-line aligned), is replaced by a counting one here.
#include <gtest/gtest.h>

#include "support/counting_aligned_allocator.hpp"

#include <cstdint>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/neighbors/dynamic_kd_tree.hpp"
#include "amp/roadmap/neighbors/kd_bounds.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"

using amp::test::g_allocations;

namespace amp::roadmap {
namespace {

using core::Joint;
using core::JointKind;

constexpr std::size_t kPoints = 4000;
constexpr int kQueries = 500;

// The Panda's seven revolute joints and their limits (../shared/mbm/panda/panda.urdf).
std::shared_ptr<core::Space> panda_like_space() {
  const double lim[7][2] = {{-2.9671, 2.9671}, {-1.8326, 1.8326}, {-2.9671, 2.9671}, {-3.1416, 0.0873},
                            {-2.9671, 2.9671}, {-0.0873, 3.8223}, {-2.9671, 2.9671}};
  std::vector<Joint> joints;
  for (int i = 0; i < 7; ++i) joints.push_back({"panda_joint" + std::to_string(i + 1), JointKind::kRevolute, lim[i][0], lim[i][1]});
  return std::make_shared<core::JointSpace>("panda", std::move(joints));
}

struct Case {
  const char* name;
  std::shared_ptr<core::Space> space;
};

std::vector<Case> cases() {
  return {{"panda7", panda_like_space()},
          {"se2", std::make_shared<core::JointSpace>(core::make_se2_space(0, 0, 1, 1, 0.7))}};
}

std::vector<State> draw(const core::Space& space, std::size_t n, std::uint64_t seed) {
  core::Rng rng(seed);
  std::vector<State> out(n);
  for (State& s : out) space.sample_uniform(rng, s);
  return out;
}

TEST(KdTreeAllocation, KNearestWithAReusedOutputAllocatesNothing) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<State> points = draw(*c.space, kPoints, 1), queries = draw(*c.space, kQueries, 2);
    core::Counters counters;  // counted queries too: the counter must not allocate either
    KdTreeNeighbors tree(*c.space, &counters);
    for (std::size_t i = 0; i < points.size(); ++i) tree.add(i, points[i]);
    std::vector<Neighbor> out;
    tree.k_nearest(queries[0], 10, out);  // the one allocation: out's capacity, reused from here on

    const long before = g_allocations.load();
    double sum = 0.0;
    std::size_t found = 0;
    for (const State& q : queries) {
      tree.k_nearest(q, 1, out);
      found += out.size();
      sum += out.front().distance;
      tree.k_nearest(q, 10, out);
      found += out.size();
      sum += out.back().distance;
    }
    EXPECT_EQ(g_allocations.load() - before, 0) << "k_nearest allocated";
    EXPECT_EQ(found, static_cast<std::size_t>(kQueries) * 11);  // every query answered in full
    EXPECT_GT(sum, 0.0);
    EXPECT_EQ(counters.nn_queries(), 2u * kQueries + 1);
  }
}

// Every stored point whose bound lies within a fixed radius: the search DynamicKdTree offers for a
// range query (KdTreeNeighbors has none), with the visitor's output reserved by the caller.
struct RadiusVisitor {
  double r;
  std::vector<std::uint32_t>* ids;
  double radius() const { return r; }
  void visit(std::uint32_t id) { ids->push_back(id); }
};

TEST(KdTreeAllocation, RadiusSearchAllocatesNothing) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<State> points = draw(*c.space, kPoints, 3), queries = draw(*c.space, kQueries, 4);
    DynamicKdTree<EmbeddingBound> tree{EmbeddingBound(*c.space)};
    for (const State& s : points) tree.insert(s);
    // The counter sees the tree's cache-line-aligned vectors (else the insertion test is blind).
    const long aligned_before = g_allocations.load();
    { std::vector<float, AlignedAllocator<float>> probe(16); }
    ASSERT_EQ(g_allocations.load() - aligned_before, 1);
    std::vector<std::uint32_t> ids;
    ids.reserve(kPoints);  // room for every point: no query can outgrow it
    // About 10 of 4000 uniform points fall within 0.1 of the extent in 2-3 D; fewer in 7-D.
    RadiusVisitor v{0.1 * c.space->maximum_extent(), &ids};

    const long before = g_allocations.load();
    std::size_t hits = 0;
    for (const State& q : queries) {
      ids.clear();
      tree.bound().prepare(q);
      tree.search(v);
      hits += ids.size();
    }
    EXPECT_EQ(g_allocations.load() - before, 0) << "the radius search allocated";
    EXPECT_GT(hits, 0u);  // the searches found something: they descended into the tree
  }
}

// Allocations of adding n points to a tree reserved for n: amortised growth only.
long insertion_allocations(const core::Space& space, const std::vector<State>& points, std::size_t n) {
  KdTreeNeighbors tree(space);
  tree.reserve(n);
  const long before = g_allocations.load();
  for (std::size_t i = 0; i < n; ++i) tree.add(i, points[i]);
  return g_allocations.load() - before;
}

// KdTreeNeighbors::reserve covers the points' coordinates and ids, not the tree's nodes, boxes and
// buckets, whose number depends on the insertion order (bucket splits, scapegoat rebuilds): those
// grow by doubling, and a full rebuild each time the size doubles reuses their capacity. So
// doubling the points adds a bounded number of allocations, never one per point.
TEST(KdTreeAllocation, InsertionAllocatesPerDoublingNotPerPoint) {
  constexpr long kPerDoubling = 12;  // measured 4 per doubling (38, 42, 46, 50 from 4000 to 32000)
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::vector<State> points = draw(*c.space, 8 * kPoints, 5);
    long previous = -1;
    for (std::size_t n = kPoints; n <= 8 * kPoints; n *= 2) {
      const long a = insertion_allocations(*c.space, points, n);
      std::cout << c.name << ": " << n << " insertions after reserve: " << a << " allocations\n";
      EXPECT_LT(a, 100) << "insertion allocates per point";
      if (previous >= 0) {
        EXPECT_LE(a - previous, kPerDoubling) << n << " points";
      }
      previous = a;
    }
  }
}

}  // namespace
}  // namespace amp::roadmap
