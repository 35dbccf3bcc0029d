// The Panda's validity check, one configuration at a time, on uniform states of MotionBenchMaker's
// box/scene0001 (../shared/mbm), as the vamp-peer's `--bench-cd` draws them: the exact meshes (FCL),
// the sphere model checked by FCL, and the sphere checker (collision: spheres). docs/arms.md,
// "Sphere model", gives the figures beside the peer's.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/rng.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/source_tree.hpp"

namespace {

namespace fs = std::filesystem;
using amp::State;

constexpr int kStates = 4096;

const fs::path kPanda = fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda";

amp::world::Problem box_problem(amp::world::ArmCollision model) {
  amp::world::ArmFiles files{kPanda / "panda.urdf", kPanda / "panda.srdf", kPanda / "problems" / "box" / "scene0001.yaml",
                             kPanda / "problems" / "box" / "request0001.yaml", {}, {}};
  files.collision.model = model;
  files.collision.cache_dir = amp::world::default_sphere_cache_dir();
  return amp::world::load_arm_problem(files);
}

std::vector<State> uniform_states(const amp::world::Problem& p) {
  amp::core::Rng rng(1);
  std::vector<State> out(kStates);
  for (State& s : out) p.space->sample_uniform(rng, s);
  return out;
}

// Arg: 0 the meshes (FCL), 1 the spheres through FCL, 2 the sphere checker.
void BM_PandaIsValid(benchmark::State& state) {
  const bool spheres = state.range(0) > 0;
  const amp::world::Problem p = box_problem(spheres ? amp::world::ArmCollision::kSpheres : amp::world::ArmCollision::kMeshes);
  const auto& env = dynamic_cast<const amp::world::ArmEnvironment&>(*p.environment);
  amp::core::Counters counters;
  const auto checker = state.range(0) == 2 ? env.make_checker(counters) : env.make_fcl_checker(counters);
  const std::vector<State> states = uniform_states(p);
  std::size_t i = 0, free = 0;
  for (auto _ : state) {
    free += checker->is_valid(states[i]) ? 1 : 0;
    i = (i + 1) % states.size();
  }
  state.counters["free"] = static_cast<double>(free) / static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PandaIsValid)->Arg(0)->Arg(1)->Arg(2);

// An edge's states, four nearby ones at a time (t = 1/64 .. 4/64 from a uniform state towards
// another), as the straight-line planner hands them over. Arg 0: one at a time, stopping at the first
// invalid; 1: blocks of four (ValidityChecker::all_valid). Items: four states per iteration.
void BM_PandaEdgeStates(benchmark::State& state) {
  const amp::world::Problem p = box_problem(amp::world::ArmCollision::kSpheres);
  amp::core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const std::vector<State> ends = uniform_states(p);
  std::vector<State> states(4 * (ends.size() - 1));
  for (std::size_t e = 0; e + 1 < ends.size(); ++e) {
    for (std::size_t k = 0; k < 4; ++k) p.space->interpolate(ends[e], ends[e + 1], static_cast<double>(k + 1) / 64.0, states[4 * e + k]);
  }
  std::size_t e = 0, free = 0;
  for (auto _ : state) {
    const State* block[4] = {&states[4 * e], &states[4 * e + 1], &states[4 * e + 2], &states[4 * e + 3]};
    bool ok = true;
    if (state.range(0) == 0) {
      for (const State* s : block) {
        if (!(ok = checker->is_valid(*s))) break;
      }
    } else {
      ok = checker->all_valid(block, 4);
    }
    free += ok ? 1 : 0;
    e = (e + 1) % (ends.size() - 1);
  }
  state.counters["free"] = static_cast<double>(free) / static_cast<double>(state.iterations());
  state.SetItemsProcessed(4 * state.iterations());
}
BENCHMARK(BM_PandaEdgeStates)->Arg(0)->Arg(1);

// The certified step's query: free_share from a state along a segment to another uniform state.
void BM_PandaFreeShare(benchmark::State& state) {
  const amp::world::Problem p = box_problem(state.range(0) > 0 ? amp::world::ArmCollision::kSpheres : amp::world::ArmCollision::kMeshes);
  amp::core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  std::vector<State> states;
  for (const State& s : uniform_states(p)) {
    if (checker->is_valid(s)) states.push_back(s);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(checker->free_share(states[i], states[i], states[(i + 1) % states.size()]));
    i = (i + 1) % states.size();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PandaFreeShare)->Arg(0)->Arg(1);

}  // namespace
