// PRM and Lazy PRM on the test narrow-gap world (point robot, 0.8-wide gap in a wall).
#include <benchmark/benchmark.h>

#include "../tests/roadmap/test_worlds.hpp"
#include "amp/roadmap/run.hpp"

namespace {

using namespace amp;

constexpr double kTimeLimit = 30.0;
constexpr std::size_t kNodeLimit = 20000;

void prm(benchmark::State& state, bool lazy) {
  const world::Problem p = roadmap::test::point_problem(true);
  std::uint64_t seed = 0, cd = 0, nodes = 0, solved = 0;
  for (auto _ : state) {
    const roadmap::RunOutcome o =
        roadmap::execute_run(p, "prm", {{"lazy", lazy}, {"k", 10}}, ++seed, kTimeLimit, kNodeLimit);
    cd += o.record.cd_calls();
    nodes += o.record.nodes;
    solved += o.record.status == core::PlanStatus::kSolved ? 1 : 0;
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["cd_calls"] = static_cast<double>(cd) / runs;
  state.counters["nodes"] = static_cast<double>(nodes) / runs;
  state.counters["solved"] = static_cast<double>(solved) / runs;
}

void BM_PrmNarrowGap(benchmark::State& state) { prm(state, false); }
void BM_LazyPrmNarrowGap(benchmark::State& state) { prm(state, true); }

}  // namespace

BENCHMARK(BM_PrmNarrowGap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LazyPrmNarrowGap)->Unit(benchmark::kMillisecond);
