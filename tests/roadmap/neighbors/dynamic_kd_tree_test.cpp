#include "amp/roadmap/neighbors/dynamic_kd_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/roadmap/neighbors/kd_bounds.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"
#include "amp/roadmap/neighbors/linear_neighbors.hpp"

namespace amp::roadmap {
namespace {

constexpr double kPi = std::numbers::pi;

State se3(double x, double y, double z, const Eigen::Quaterniond& q) {
  return core::Se3Space::make_state(Eigen::Vector3d(x, y, z), q);
}

// Inserts `states` in order into a KdTreeNeighbors and a LinearNeighbors, querying both along the
// way (before the first insertion too), and expects identical answers.
void expect_same_as_brute_force(const core::Space& space, const std::vector<State>& states,
                                const std::vector<State>& queries) {
  KdTreeNeighbors tree(space);
  LinearNeighbors brute(space);
  std::vector<Neighbor> got, want;
  std::size_t next_query = 0;
  for (std::size_t i = 0; i <= states.size(); ++i) {
    if (i % 97 == 0 || i == states.size()) {
      for (std::size_t k : {1, 3, 10, 40}) {
        const State& q = queries[next_query++ % queries.size()];
        tree.k_nearest(q, k, got);
        brute.k_nearest(q, k, want);
        ASSERT_EQ(got, want) << "after " << i << " states, k = " << k;
      }
    }
    if (i < states.size()) {
      tree.add(7 * i + 2, states[i]);
      brute.add(7 * i + 2, states[i]);
    }
  }
}

TEST(Se3Bound, AngleFromChordIsALowerBoundAndTightNearZero) {
  for (double angle = 0.0; angle <= kPi; angle += 0.01) {
    const double chord = 2.0 * std::sin(angle / 4.0);
    EXPECT_LE(Se3Bound::angle_from_chord(chord), angle + 1e-15);
    if (angle < 1.0) {
      EXPECT_NEAR(Se3Bound::angle_from_chord(chord), angle, 1e-3 * angle);
    }
  }
  EXPECT_NEAR(Se3Bound::angle_from_chord(0.5), 4.0 * std::asin(0.25), 2e-5);
}

TEST(Se3Bound, PointAndBoxBoundsNeverExceedTheDistance) {
  const core::Se3Space space(Eigen::Vector3d(-1, -2, 0), Eigen::Vector3d(3, 2, 1), 2.5, 0.7);
  Se3Bound bound(*space.coordinate_layout());
  core::Rng rng(11);
  for (int i = 0; i < 2000; ++i) {
    State a, b;
    space.sample_uniform(rng, a);
    space.sample_uniform(rng, b);
    double x[7];
    bound.store(b, x);
    float xf[7], lo[7], hi[7];
    for (int d = 0; d < 7; ++d) {
      xf[d] = static_cast<float>(x[d]);
      // A box around the point that reaches no further than 0.2 from it on each coordinate.
      lo[d] = static_cast<float>(x[d] - rng.uniform(0.0, 0.2)) - 1e-6f;
      hi[d] = static_cast<float>(x[d] + rng.uniform(0.0, 0.2)) + 1e-6f;
    }
    bound.prepare(a);
    const double d = space.distance(a, b);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_LE(bound.point(xf, inf), d + bound.float_slack(5.0) + bound.slack());
    EXPECT_LE(bound.box(lo, hi, inf), d + bound.slack());
    // The early outs only ever report "beyond r" for a state truly beyond r.
    EXPECT_LE(bound.box(lo, hi, 1.01 * d + 1e-9), 1.01 * d + 1e-9);
  }
  // Exact on the point itself, whatever the sign of its quaternion.
  State a = se3(0.5, 0.5, 0.5, Eigen::Quaterniond(0.3, 0.1, -0.9, 0.2));
  State minus_a = a;
  minus_a.tail<4>() *= -1.0;
  double x[7];
  bound.store(minus_a, x);
  float xf[7];
  for (int d = 0; d < 7; ++d) xf[d] = static_cast<float>(x[d]);
  bound.prepare(a);
  EXPECT_NEAR(bound.point(xf, 1.0), 0.0, 1e-6);
}

TEST(KdTreeNeighbors, Se3EqualsBruteForceForUnequalWeights) {
  const core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(4, 1, 2), 3.0, 0.5);
  core::Rng rng(3);
  std::vector<State> states(1200), queries(64);
  for (State& s : states) space.sample_uniform(rng, s);
  for (State& s : queries) space.sample_uniform(rng, s);
  expect_same_as_brute_force(space, states, queries);
}

TEST(KdTreeNeighbors, Se3NearTheDoubleCoverBoundaryAndTies) {
  const core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 1.0);
  core::Rng rng(5);
  std::vector<State> states, queries;
  for (int i = 0; i < 900; ++i) {
    // w ~ 0 (angle ~ pi): q and -q both near; a 3x3x3 grid of positions, three orientations, so
    // many states are duplicates or tie exactly.
    const Eigen::Quaterniond q(rng.uniform(-0.02, 0.02), 1.0, rng.uniform(-0.1, 0.1), 0.0);
    const auto g = [&] { return 0.5 * static_cast<double>(rng.uniform_index(3)); };
    const Eigen::Quaterniond fixed[3] = {Eigen::Quaterniond(0, 1, 0, 0), Eigen::Quaterniond(0, -1, 0, 0),
                                         Eigen::Quaterniond::Identity()};
    states.push_back(i % 2 == 0 ? se3(g(), g(), g(), q) : se3(g(), g(), g(), fixed[rng.uniform_index(3)]));
    State minus = states.back();
    minus.tail<4>() *= -1.0;
    if (i % 5 == 0) states.push_back(minus);  // the same state written with -q
  }
  for (int i = 0; i < 40; ++i) {
    queries.push_back(se3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1),
                          Eigen::Quaterniond(rng.uniform(-0.05, 0.05), rng.uniform(-1, 1), 0.1, 0.0)));
    queries.push_back(states[rng.uniform_index(states.size())]);  // exact duplicates of stored states
  }
  expect_same_as_brute_force(space, states, queries);
}

TEST(KdTreeNeighbors, AdversarialOrdersOnEverySpace) {
  std::vector<std::shared_ptr<core::Space>> spaces = {
      std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {1, 1})),
      std::make_shared<core::JointSpace>(core::make_se2_space(0, 0, 1, 1, 0.5)),
      std::make_shared<core::Se3Space>(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 0.3)};
  for (const auto& space : spaces) {
    SCOPED_TRACE(std::string(space->kind()));
    core::Rng rng(9);
    std::vector<State> states(1500), queries(50);
    for (State& s : states) space->sample_uniform(rng, s);
    for (State& s : queries) space->sample_uniform(rng, s);
    // Sorted along x: every insertion lands in the same corner of the tree.
    std::vector<std::size_t> order(states.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return states[a][0] < states[b][0]; });
    std::vector<State> sorted;
    for (std::size_t i : order) sorted.push_back(states[i]);
    expect_same_as_brute_force(*space, sorted, queries);
    // One state repeated: boxes of zero width.
    expect_same_as_brute_force(*space, std::vector<State>(300, states[17]), queries);
  }
}

// A tree searched with a brute-force visitor keeps its depth logarithmic under sorted insertion.
struct CollectAll {
  double radius() const { return std::numeric_limits<double>::infinity(); }
  void visit(std::uint32_t id) { ids.push_back(id); }
  std::vector<std::uint32_t> ids;
};

TEST(DynamicKdTree, StaysBalancedUnderSortedInsertionAndKeepsEveryPoint) {
  const core::JointSpace space = core::make_rn_space({0, 0}, {1, 1});
  DynamicKdTree<EmbeddingBound> tree{EmbeddingBound(space)};
  constexpr std::size_t kN = 20000;
  for (std::size_t i = 0; i < kN; ++i) {
    const double t = static_cast<double>(i) / kN;
    tree.insert((State(2) << t, t * t).finished());
  }
  EXPECT_EQ(tree.size(), kN);
  // Scapegoat bound: depth <= log_{4/3}(n) + 3 (about 37 here); a chain would be ~kN / 8.
  EXPECT_LE(static_cast<double>(tree.depth()), std::log(static_cast<double>(kN)) / std::log(4.0 / 3.0) + 3.0);
  CollectAll all;
  tree.bound().prepare((State(2) << 0.5, 0.5).finished());
  tree.search(all);
  std::sort(all.ids.begin(), all.ids.end());
  ASSERT_EQ(all.ids.size(), kN);
  for (std::size_t i = 0; i < kN; ++i) ASSERT_EQ(all.ids[i], i);
}

TEST(KdTreeNeighbors, PrunesOnLargeSe3Sets) {
  const core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10), 1.0);
  KdTreeNeighbors tree(space);
  core::Rng rng(1);
  State s;
  for (std::size_t i = 0; i < 20000; ++i) {
    space.sample_uniform(rng, s);
    tree.add(i, s);
  }
  std::vector<Neighbor> out;
  std::size_t evaluations = 0;
  for (int i = 0; i < 50; ++i) {
    space.sample_uniform(rng, s);
    tree.k_nearest(s, 10, out);
    evaluations += tree.last_distance_evaluations();
  }
  // The block bound leaves a few dozen true distances per query, not thousands.
  EXPECT_LT(evaluations / 50, 200u);
}

}  // namespace
}  // namespace amp::roadmap
