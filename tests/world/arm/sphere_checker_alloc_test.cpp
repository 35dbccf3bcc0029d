// The sphere checker's hot calls allocate nothing once made: is_valid, clearance, free_radius,
// free_share, and the certifier and straight-line edge checks built on them, on a shared Panda
// scene in the sphere model. Global operator new is replaced by a counting one in this executable.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "amp/core/rng.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

using amp::test::g_allocations;

namespace amp::world {
namespace {

namespace fs = std::filesystem;

TEST(SphereCheckerAllocation, HotCallsAllocateNothing) {
  const fs::path panda = fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda";
  ArmFiles files{panda / "panda.urdf", panda / "panda.srdf", panda / "problems" / "box" / "scene0001.yaml",
                 panda / "problems" / "box" / "request0001.yaml", {}, {ArmCollision::kSpheres, {}, test::shared_sphere_cache()}};
  const Problem p = load_arm_problem(files);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  roadmap::EdgeCertifier certifier(*p.space, *checker);
  roadmap::StraightLinePlanner lp(*p.space, *checker);
  core::Rng rng(3);
  std::vector<State> states(300);
  for (State& s : states) p.space->sample_uniform(rng, s);
  // Warm-up: scratch buffers grow to the longest edge.
  for (std::size_t i = 0; i + 1 < states.size(); ++i) lp.connect(states[i], states[i + 1]);
  lp.connect(p.start(), p.goal());

  const long before = g_allocations.load();
  int valid = 0, certified = 0, connected = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < states.size(); ++i) {
    const State &a = states[i], &b = states[i + 1];
    if (!checker->is_valid(a)) continue;
    ++valid;
    sum += checker->clearance(a).distance + checker->free_radius(a) + checker->free_share(a, a, b);
    if (checker->is_valid(b)) certified += certifier.certify(a, b) ? 1 : 0;
    connected += lp.connect(a, b) ? 1 : 0;
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "the sphere checker's calls allocated";
  // The loop did real work: valid states, certified and connected edges, positive distances.
  EXPECT_GT(valid, 50);
  EXPECT_GT(certified + connected, 5);
  EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace amp::world
