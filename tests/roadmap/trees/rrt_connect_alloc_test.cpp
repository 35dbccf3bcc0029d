// RRT-Connect's EXTEND and CONNECT steps allocate nothing per step (issue 36, item 4). They are
// private to rrt_connect.cpp, so the test measures whole runs through the public planner: the same
// unsolved problem, the same seed, node limits N, 2N and 4N. Each run does everything the shorter
// one did and then thousands of steps more (each a nearest-node query, an interpolation, a validity
// check, an edge check and an insertion), so a per-step allocation would add thousands; the tree's
// vectors growing by doubling add a few per doubling, whatever N. Global operator new, aligned
// forms included (the KD-tree's boxes are cache-line aligned), is replaced by a counting one here.
#include <gtest/gtest.h>

#include "support/counting_aligned_allocator.hpp"

#include <filesystem>
#include <iostream>
#include <string>

#include "amp/core/rng.hpp"
#include "amp/roadmap/trees/rrt_connect.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/problem.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

using amp::test::g_allocations;

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;

constexpr double kNoTimeLimit = 1e6;  // the node limit ends every run, never the clock
// Above kMaxCopiedFailedTrees (5000 in rrt_connect.cpp): an unsolved run's trees are then only
// counted, not copied into the result's roadmap (a copy allocates per node, after the search).
constexpr std::size_t kN = 6000;
// Allowed growth of the allocation count from one run to the next (2x the nodes); one allocation
// per step would add at least N = 6000. What does grow: each KD-tree has 8 vectors that are not
// reserved (nodes, boxes, bucket ids and coordinates, two free lists, two scratch vectors), each
// allocating about log2 of its size over a run, and a tree whose share of the nodes grows from a
// few hundred to thousands (the Panda's lopsided trees) takes several doublings of each at once.
// Measured: sealed 8 and 15 (discrete and certified alike), Panda 59 then 11.
constexpr long kPerDoubling = 96;

struct Measured {
  long allocations = 0;
  PlanResult result;
  std::uint64_t cd_calls = 0;
};

Measured run(const world::Problem& p, std::size_t node_limit, RrtConnectSettings settings, core::EdgeCheckMode mode) {
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds, mode};
  const core::StopCondition stop(kNoTimeLimit, node_limit);
  RrtConnect planner(settings);
  core::Rng rng(7);
  Measured m;
  const long before = g_allocations.load();
  m.result = planner.plan(ctx, stop, rng);
  m.allocations = g_allocations.load() - before;
  m.cd_calls = counters.cd_calls();
  return m;
}

// Runs at N, 2N and 4N nodes, all stopped by the node limit, and bounds the allocation growth.
void expect_no_allocation_per_step(const world::Problem& p, RrtConnectSettings settings, core::EdgeCheckMode mode,
                                   const std::string& label) {
  run(p, 100, settings, mode);  // warm-up: first-use statics (settings schema, checker tables)
  Measured previous;
  for (std::size_t n = kN; n <= 4 * kN; n *= 2) {
    const Measured m = run(p, n, settings, mode);
    ASSERT_EQ(m.result.status, core::PlanStatus::kNodeLimit) << label << ": the problem must stay unsolved";
    ASSERT_EQ(m.result.nodes, n);
    std::cout << label << ": " << n << " nodes, " << m.cd_calls << " collision checks, " << m.allocations
              << " allocations\n";
    if (n > kN) {
      EXPECT_GT(m.cd_calls, previous.cd_calls + n / 2) << label << ": the longer run took thousands more steps";
      EXPECT_LE(m.allocations - previous.allocations, kPerDoubling)
          << label << ": " << n << " nodes allocated more than a doubling's worth over " << n / 2;
    }
    previous = m;
  }
}

// Planar: a disc robot whose goal is sealed in a box (the stop-mechanism tests' problem), with the
// real planar checker and the default range, in both edge modes.
TEST(RrtConnectAllocation, PlanarSealedGoalAllocatesPerDoublingNotPerStep) {
  const world::Problem p = world::load_problem(fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data" / "sealed.yaml");
  expect_no_allocation_per_step(p, {}, core::EdgeCheckMode::kDiscrete, "sealed, discrete");
  expect_no_allocation_per_step(p, {}, core::EdgeCheckMode::kCertified, "sealed, certified");
}

// The shared Panda in its box scene, sphere model. RRT-Connect solves it in a few hundred nodes at
// the default range, so the range is cut until meeting is impossible within the limit: a meeting
// needs a chain of tree edges (at most `range` each, at most 4N + 1 of them with the meeting edge)
// from start to goal, so with range = d(start, goal) / (4N + 2) the triangle inequality keeps every
// run unsolved. The steps are short, but each is a whole EXTEND or CONNECT step of the Panda.
TEST(RrtConnectAllocation, PandaAllocatesPerDoublingNotPerStep) {
  const fs::path panda = fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda";
  if (!fs::exists(panda / "panda.urdf")) GTEST_SKIP() << "needs ../shared/mbm/panda";
  world::ArmFiles files{panda / "panda.urdf", panda / "panda.srdf", panda / "problems" / "box" / "scene0001.yaml",
                        panda / "problems" / "box" / "request0001.yaml", {},
                        {world::ArmCollision::kSpheres, {}, test::shared_sphere_cache()}};
  const world::Problem p = world::load_arm_problem(files);
  RrtConnectSettings settings;
  settings.range = p.space->distance(p.start(), p.goal()) / static_cast<double>(4 * kN + 2);
  expect_no_allocation_per_step(p, settings, core::EdgeCheckMode::kDiscrete, "panda box, discrete");
}

}  // namespace
}  // namespace amp::roadmap
