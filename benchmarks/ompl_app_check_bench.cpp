// Raw validity checks per second on OMPL.app's own problems, loaded from their .cfg exactly as
// `amp plan` loads them, on uniform states of the problem's space (as ompl-peer's --bench-cd draws
// them), so that the rate reads side by side with OMPL + FCL's. The problems are looked up in
// $AMP_OMPLAPP_DIR, else ../shared/omplapp beside the source tree; a case skips when absent.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/rng.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace {

constexpr int kStates = 200000;  // pre-drawn and cycled, so sampling is not timed

std::filesystem::path omplapp_dir() {
  if (const char* env = std::getenv("AMP_OMPLAPP_DIR")) return env;
  return std::filesystem::path(AMP_SOURCE_DIR) / "../shared/omplapp";
}

void run(benchmark::State& state, const std::string& stem) {
  const std::filesystem::path file = omplapp_dir() / (stem + ".cfg");
  if (!std::filesystem::exists(file)) {
    state.SkipWithError(("no " + file.string() + " (set AMP_OMPLAPP_DIR)").c_str());
    return;
  }
  const amp::world::Problem problem = amp::world::load_problem(file);
  amp::core::Counters counters;
  const auto checker = problem.environment->make_checker(counters);
  amp::core::Rng rng(7);
  std::vector<amp::State> states(kStates, amp::State(problem.space->dimension()));
  for (auto& s : states) problem.space->sample_uniform(rng, s);
  std::size_t i = 0, valid = 0;
  for (auto _ : state) {
    const bool v = checker->is_valid(states[i]);
    valid += v;
    benchmark::DoNotOptimize(v);
    i = i + 1 == states.size() ? 0 : i + 1;
  }
  state.counters["checks"] = benchmark::Counter(static_cast<double>(counters.cd_calls()), benchmark::Counter::kIsRate);
  state.counters["valid_fraction"] = static_cast<double>(valid) / static_cast<double>(state.iterations());
}

void BM_MazePlanarCheck(benchmark::State& state) { run(state, "Maze_planar"); }
void BM_BugTrapPlanarCheck(benchmark::State& state) { run(state, "BugTrap_planar"); }
void BM_TwistycoolCheck(benchmark::State& state) { run(state, "Twistycool"); }

}  // namespace

BENCHMARK(BM_MazePlanarCheck);
BENCHMARK(BM_BugTrapPlanarCheck);
BENCHMARK(BM_TwistycoolCheck);
