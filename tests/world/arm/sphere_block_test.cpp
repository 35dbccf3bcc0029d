// The sphere checker's blocks (ValidityChecker::all_valid): a block of configurations posed together
// in SIMD lanes (src/world/arm/block_kinematics.cpp) gets, state by state, the verdict the checker
// gives each state alone, whatever its lane and its neighbours, and counts one CD call per state;
// the straight-line planner's blocked edges keep the verdicts of one state at a time. The block
// kinematics is checked against FCL on the same spheres for a robot with a slide, a continuous
// joint and a fixed one (tests/data/arm/two_link), besides the Panda's turns about z
// (sphere_checker_test.cpp, AgreesWithFclOnTheSameSpheres).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/edge_steps.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sanitizer_build.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

fs::path panda_dir() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda"; }
fs::path two_link_dir() { return fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link"; }

const ArmEnvironment& arm(const Problem& p) { return dynamic_cast<const ArmEnvironment&>(*p.environment); }

Problem panda_problem(const std::string& family) {
  static const ArmDescription robot = load_arm_description(
      panda_dir() / "panda.urdf", panda_dir() / "panda.srdf", {}, ArmCollisionOptions{ArmCollision::kSpheres, {}, test::shared_sphere_cache()});
  const fs::path dir = panda_dir() / "problems" / family;
  return load_arm_problem(robot, dir / "scene0001.yaml", dir / "request0001.yaml");
}

// Blocks of 1 to 4 states along drawn segments: all_valid says whether each is valid alone, counts
// one CD call per state, and a state's verdict does not depend on its lane.
TEST(SphereBlocks, BlockVerdictIsEveryStatesOwn) {
  // 1500 blocks per problem, 375 under the sanitizers; each kind of verdict at least one in 15.
  const int blocks = test::case_share(1500);
  for (const std::string family : {"box", "table_pick", "bookshelf_small"}) {
    const Problem p = panda_problem(family);
    ASSERT_TRUE(arm(p).sphere_checked()) << family;
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    ASSERT_EQ(checker->block_size(), 4u);
    core::Rng rng(31);
    State a, b;
    std::array<State, 4> block;
    std::array<const State*, 4> refs{};
    int valid_blocks = 0, invalid_blocks = 0;
    for (int i = 0; i < blocks; ++i) {
      p.space->sample_uniform(rng, a);
      p.space->sample_uniform(rng, b);
      const std::size_t n = 1 + static_cast<std::size_t>(i % 4);
      // Nearby states (a short stretch of the segment), as an edge's blocks are.
      bool all = true;
      for (std::size_t k = 0; k < n; ++k) {
        p.space->interpolate(a, b, 0.02 * static_cast<double>(k), block[k]);
        refs[k] = &block[k];
        all = checker->is_valid(block[k]) && all;
      }
      const std::uint64_t before = counters.cd_calls();
      ASSERT_EQ(checker->all_valid(refs.data(), n), all) << family << ", block " << i;
      EXPECT_EQ(counters.cd_calls() - before, n);
      (all ? valid_blocks : invalid_blocks) += 1;
      // The block reversed puts every state in another lane: the same verdict.
      std::array<const State*, 4> reversed{};
      for (std::size_t k = 0; k < n; ++k) reversed[k] = refs[n - 1 - k];
      ASSERT_EQ(checker->all_valid(reversed.data(), n), all) << family << ", block " << i << " reversed";
    }
    EXPECT_GT(valid_blocks, blocks / 15) << family;
    EXPECT_GT(invalid_blocks, blocks / 15) << family;
  }
}

// The straight-line planner checks an edge a block at a time: its verdict is the same as checking
// the edge's states one by one at the same resolution.
TEST(SphereBlocks, StraightLineEdgesKeepTheirVerdicts) {
  const Problem p = panda_problem("box");
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  roadmap::StraightLinePlanner lp(*p.space, *checker);
  core::Rng rng(37);
  State a, b, at;
  int free = 0, blocked = 0;
  for (int i = 0; i < 400; ++i) {
    p.space->sample_uniform(rng, a);
    p.space->sample_uniform(rng, b);
    p.space->interpolate(a, b, 0.15, b);  // short edges, so that both verdicts occur
    const std::int64_t segments = core::edge_segments(p.space->distance(a, b), p.space->resolution());
    bool expected = true;
    for (std::int64_t s = 1; s < segments; ++s) {
      p.space->interpolate(a, b, static_cast<double>(s) / static_cast<double>(segments), at);
      expected = expected && checker->is_valid(at);
    }
    ASSERT_EQ(lp.connect(a, b), expected) << "edge " << i;
    (expected ? free : blocked) += 1;
  }
  EXPECT_GT(free, 40);
  EXPECT_GT(blocked, 40);
}

// A slide, a continuous joint and a fixed one, posed in blocks: clearances equal FCL's on the same
// spheres.
TEST(SphereBlocks, TwoLinkArmAgreesWithFclOnTheSameSpheres) {
  const ArmDescription robot = load_arm_description(two_link_dir() / "two_link.urdf", two_link_dir() / "two_link.srdf", {},
                                                    ArmCollisionOptions{ArmCollision::kSpheres, {}, test::shared_sphere_cache()});
  const Problem p = load_arm_problem(robot, two_link_dir() / "scene.yaml", two_link_dir() / "request.yaml");
  ASSERT_TRUE(arm(p).sphere_checked());
  core::Counters counters;
  const auto fast = p.environment->make_checker(counters);
  const auto fcl = arm(p).make_fcl_checker(counters);
  core::Rng rng(41);
  State s;
  int valid = 0;
  for (int i = 0; i < 2000; ++i) {
    p.space->sample_uniform(rng, s);
    const double reference = fcl->clearance(s).distance;
    ASSERT_NEAR(fast->clearance(s).distance, reference, 1e-5) << "state " << i;
    if (reference > 1e-5) {  // clear of the scene: the verdicts (self-collision too) agree
      const bool verdict = fcl->is_valid(s);
      ASSERT_EQ(fast->is_valid(s), verdict) << "state " << i;
      valid += verdict ? 1 : 0;
    }
  }
  EXPECT_GT(valid, 100);
}

}  // namespace
}  // namespace amp::world
