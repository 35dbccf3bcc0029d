// PRM on every bundled problem (seeds 1, 2, ... per iteration) and on the narrow-gap test world.
// Counters: mean CD calls, nodes and solved fraction per run. The median / 95th percentile over 50
// seeds come from `amp bench problems/experiments/prm-baseline.yaml` (summary.json).
#include <benchmark/benchmark.h>

#include <string>

#include "../tests/roadmap/test_worlds.hpp"
#include "amp/roadmap/run.hpp"
#include "support/source_tree.hpp"

namespace {

using namespace amp;

constexpr double kTimeLimit = 30.0;
constexpr std::size_t kNodeLimit = 50000;

void run_prm(benchmark::State& state, const world::Problem& p, const core::ParamMap& params) {
  std::uint64_t seed = 0, cd = 0, nodes = 0, solved = 0;
  for (auto _ : state) {
    const roadmap::RunOutcome o = roadmap::execute_run(p, "prm", params, ++seed, kTimeLimit, kNodeLimit);
    cd += o.record.cd_calls();
    nodes += o.record.nodes;
    solved += o.record.status == core::PlanStatus::kSolved ? 1 : 0;
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["cd_calls"] = static_cast<double>(cd) / runs;
  state.counters["nodes"] = static_cast<double>(nodes) / runs;
  state.counters["solved"] = static_cast<double>(solved) / runs;
}

void BM_PrmNarrowGap(benchmark::State& state) { run_prm(state, roadmap::test::point_problem(true), {{"k", 10}}); }
void BM_LazyPrmNarrowGap(benchmark::State& state) {
  run_prm(state, roadmap::test::point_problem(true), {{"lazy", true}, {"k", 10}});
}

void BM_PrmBundled(benchmark::State& state, const std::string& file) {
  const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/" + file);
  run_prm(state, p, {});
}

}  // namespace

BENCHMARK(BM_PrmNarrowGap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LazyPrmNarrowGap)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, maze, std::string("maze.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, l_tunnel, std::string("l-tunnel.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, hook, std::string("hook.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, walls, std::string("walls.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, linkage, std::string("linkage.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, maze3d, std::string("maze3d.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, walls3d, std::string("walls3d.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, office_map, std::string("office-map.yaml"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrmBundled, movingai_rooms, std::string("movingai-rooms.yaml"))->Unit(benchmark::kMillisecond);
