#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/roadmap/neighbors/linear_neighbors.hpp"

namespace amp::roadmap {
namespace {

using core::Joint;
using core::JointKind;
constexpr double kPi = std::numbers::pi;

// Draws a state; `hard` concentrates them where the embedding is loosest (angles near +-pi,
// quaternions near the q / -q boundary w = 0).
using Draw = State (*)(const core::Space&, core::Rng&);

State uniform(const core::Space& space, core::Rng& rng) {
  State s;
  space.sample_uniform(rng, s);
  return s;
}

State se2_near_pi(const core::Space& space, core::Rng& rng) {
  State s = uniform(space, rng);
  s[2] = core::wrap_angle(kPi + rng.uniform(-0.3, 0.3));
  return s;
}

State se3_near_boundary(const core::Space& /*space*/, core::Rng& rng) {
  const Eigen::Vector3d p(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1));
  // Rotations of angle near pi about axes near x: w ~ 0, so q and -q are close to the same state.
  const Eigen::Quaterniond q(rng.uniform(-0.05, 0.05), 1.0, rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2));
  return core::Se3Space::make_state(p, q);
}

State grid_point(const core::Space& /*space*/, core::Rng& rng) {
  // Integer grid: many exact distance ties, resolved by index.
  return (State(2) << static_cast<double>(rng.uniform_index(6)), static_cast<double>(rng.uniform_index(6))).finished();
}

struct Case {
  const char* name;
  std::shared_ptr<core::Space> space;
  Draw draw;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"rn2", std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10})), uniform});
  c.push_back({"rn2_ties", std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10})), grid_point});
  c.push_back({"rn3", std::make_shared<core::JointSpace>(core::make_rn_space({0, 0, 0}, {1, 2, 3})), uniform});
  c.push_back({"se2", std::make_shared<core::JointSpace>(core::make_se2_space(0, 0, 1, 1, 0.7)), uniform});
  c.push_back({"se2_pi", std::make_shared<core::JointSpace>(core::make_se2_space(0, 0, 1, 1, 3.0)), se2_near_pi});
  c.push_back({"se3", std::make_shared<core::Se3Space>(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 0.5),
               uniform});
  c.push_back({"se3_boundary",
               std::make_shared<core::Se3Space>(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 2.0),
               se3_near_boundary});
  c.push_back({"linkage", std::make_shared<core::JointSpace>(
                              "linkage", std::vector<Joint>{{"a", JointKind::kContinuous, 0, 0, 1.5},
                                                            {"b", JointKind::kRevolute, -2.5, 2.5, 1.0},
                                                            {"c", JointKind::kContinuous, 0, 0, 0.5},
                                                            {"d", JointKind::kLinear, 0, 1, 2.0}}),
               uniform});
  return c;
}

TEST(KdTreeNeighbors, EqualsBruteForceOnEverySpace) {
  std::size_t evaluations = 0, queries = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    core::Rng rng(7);
    KdTreeNeighbors tree(*c.space);
    LinearNeighbors brute(*c.space);
    std::vector<Neighbor> got, want;
    // Interleave insertions and queries so that queries see every stage of the dynamic tree.
    for (std::size_t i = 0; i < 1500; ++i) {
      const State s = c.draw(*c.space, rng);
      tree.add(3 * i + 1, s);  // sparse indices
      brute.add(3 * i + 1, s);
      if (i % 50 == 0 || i < 20 || i + 1 == 1500) {
        for (std::size_t k : {1, 2, 10, 37}) {
          const State q = c.draw(*c.space, rng);
          tree.k_nearest(q, k, got);
          brute.k_nearest(q, k, want);
          ASSERT_EQ(got.size(), std::min(k, i + 1));
          ASSERT_EQ(got, want) << "after " << i + 1 << " states, k = " << k;
          if (i + 1 == 1500) {
            evaluations += tree.last_distance_evaluations();
            ++queries;
          }
        }
      }
    }
    EXPECT_EQ(tree.size(), 1500u);
  }
  // The tree pruned: far fewer true distances than brute force's 1500 per query.
  EXPECT_LT(evaluations / queries, 600u);
}

TEST(KdTreeNeighbors, EmptyAndDuplicateStates) {
  const core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 1.0);
  KdTreeNeighbors nn(space);
  std::vector<Neighbor> out{{1, 1.0}};
  const State s = core::Se3Space::make_state(Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Quaterniond::Identity());
  nn.k_nearest(s, 3, out);
  EXPECT_TRUE(out.empty());
  State minus = s;
  minus.tail<4>() *= -1.0;  // the same rotation written as -q
  nn.add(4, s);
  nn.add(2, minus);
  nn.add(3, s);
  nn.k_nearest(s, 5, out);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].index, 2u);  // all at distance 0: by index
  EXPECT_EQ(out[1].index, 3u);
  EXPECT_EQ(out[2].index, 4u);
  for (const Neighbor& n : out) EXPECT_NEAR(n.distance, 0.0, 1e-7);
}

TEST(KdTreeNeighbors, CountsQueries) {
  const core::JointSpace space = core::make_rn_space({0, 0}, {1, 1});
  core::Counters counters;
  KdTreeNeighbors tree(space, &counters);
  LinearNeighbors brute(space, &counters);
  std::vector<Neighbor> out;
  tree.add(0, (State(2) << 0.5, 0.5).finished());
  tree.k_nearest((State(2) << 0, 0).finished(), 1, out);
  brute.k_nearest((State(2) << 0, 0).finished(), 1, out);
  tree.k_nearest((State(2) << 0, 0).finished(), 1, out);
  EXPECT_EQ(counters.nn_queries(), 3u);
}

}  // namespace
}  // namespace amp::roadmap
