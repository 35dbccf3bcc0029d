// An edge check allocates nothing once its scratch has grown to the longest edge seen (STYLE rule 5):
// global operator new is replaced by a counting one in this test executable only.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "amp/roadmap/straight_line_planner.hpp"
#include "amp/world/problem.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

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

}  // namespace
}  // namespace amp::roadmap
