// An edge check allocates nothing once its scratch has grown to the longest edge seen (no allocation in hot loops):
// global operator new is replaced by a counting one in this test executable only.
#include <gtest/gtest.h>

#include "support/counting_allocator.hpp"

#include "amp/roadmap/competence/grid_astar_planner.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

using amp::test::g_allocations;

namespace amp::roadmap {
namespace {

TEST(EdgeCheckAllocation, StraightLineEdgesOnTheBundledMazeAllocateNothingAfterWarmUp) {
  const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/maze.yaml");
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  StraightLinePlanner lp(*p.space, *checker);
  core::Rng rng(5);
  std::vector<State> states(200);
  for (auto& s : states) p.space->sample_uniform(rng, s);
  // Warm-up: the longest possible edge sizes the bisection-order buffer once.
  State lo(3), hi(3);
  lo << 0.0, 0.0, -3.0;
  hi << 96.0, 48.0, 3.0;
  lp.connect(lo, hi);
  const long before = g_allocations.load();
  int free_edges = 0;
  for (std::size_t i = 0; i + 1 < states.size(); ++i) free_edges += lp.connect(states[i], states[i + 1]) ? 1 : 0;
  EXPECT_EQ(g_allocations.load() - before, 0) << "edge checks allocated";
  EXPECT_GT(counters.cd_calls(), 199u);
  (void)free_edges;
}

// The A* grid planner keeps its hash table, nodes and heaps between calls: once they have grown to
// the largest search, searching again allocates nothing (none per expanded cell). On the planar arm,
// whose checker allocates nothing (FCL's checks of the SCARA's cylinders do).
TEST(EdgeCheckAllocation, GridAStarOnTheArmAllocatesNothingOnceGrown) {
  const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/linkage.yaml");
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  GridAStarPlanner astar(*p.space, *checker);
  astar.set_threshold(8.0);
  core::Rng rng(3);
  std::vector<State> states;
  State s;
  while (states.size() < 40) {
    p.space->sample_uniform(rng, s);
    if (checker->is_valid(s)) states.push_back(s);
  }
  std::size_t cells = 0;
  for (std::size_t i = 0; i + 1 < states.size(); ++i) astar.connect(states[i], states[i + 1]);  // grows
  const long before = g_allocations.load();
  for (std::size_t i = 0; i + 1 < states.size(); ++i) {
    astar.connect(states[i], states[i + 1]);
    cells += astar.last().cells_checked;
  }
  EXPECT_EQ(g_allocations.load() - before, 0) << "A* searches allocated";
  EXPECT_GT(cells, 1000u);
}

}  // namespace
}  // namespace amp::roadmap
