// Straight-line edge checks in the test box world: free edges (every state checked) and blocked
// edges (bisection finds the wall early).
#include <vector>

#include <benchmark/benchmark.h>

#include "../tests/roadmap/test_worlds.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"

namespace {

using namespace amp;

constexpr std::size_t kEdges = 1024;

void edges(benchmark::State& state, bool blocked) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  roadmap::test::BoxEnvironment env({{4.5, 0.0, 5.5, 10.0}}, roadmap::test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = env.make_checker(counters);
  roadmap::StraightLinePlanner lp(space, *checker);
  core::Rng rng(1);
  std::vector<std::pair<State, State>> list;
  // Edges of length ~ 3 (about 21 states at resolution 0.141), all left of the wall or across it.
  for (std::size_t i = 0; i < kEdges; ++i) {
    const double y0 = rng.uniform(0, 10), y1 = rng.uniform(0, 10);
    list.emplace_back(roadmap::test::state2(blocked ? 3.5 : 0.5, y0), roadmap::test::state2(blocked ? 6.5 : 3.5, y1));
  }
  std::size_t i = 0;
  std::uint64_t ok = 0;
  for (auto _ : state) {
    const auto& [a, b] = list[i++ % kEdges];
    ok += lp.connect(a, b) ? 1 : 0;
  }
  benchmark::DoNotOptimize(ok);
  state.counters["cd_per_edge"] =
      benchmark::Counter(static_cast<double>(counters.cd_calls()) / static_cast<double>(state.iterations()));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_EdgeFree(benchmark::State& state) { edges(state, false); }
void BM_EdgeBlocked(benchmark::State& state) { edges(state, true); }

}  // namespace

BENCHMARK(BM_EdgeFree);
BENCHMARK(BM_EdgeBlocked);
