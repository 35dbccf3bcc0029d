// SINS (Ram & Santamaria 1993) at its three time scales:
// - BM_MotorSchemaStep: one control step, MotorSchemas::velocity on a ring of 16 readings (AuRA's
//   avoid + goal + noise sum). Target: <= 2 us.
// - BM_CaseBasedEndInterval: one control-interval update of the adaptive system
//   (CaseBasedParameters::end_interval: perceive, retrieve, adapt, learn) with 10 cases of length 20.
//   CaseBasedParameters takes no ready library, so the library is filled by the policy itself: with
//   a new-case threshold near 1 every full history that matches badly becomes a case, and random
//   inputs fill the 10 slots in the warm-up (state.counters["cases"] says how many it reached).
// - BM_SinsPlusEndInterval: the same for sins-plus (SplittingCaseParameters::end_interval: reward,
//   retrieve, explore, and every refit_every credited uses a fit or a split), its library grown by
//   the warm-up (state.counters["cases"]).
// - BM_AdaptiveSequence, BM_SinsPlusSequence: a whole 200-world sequence of the adaptive system
//   (sins-plus) at 25% clutter at the calibrated scale (run_sequence, as one `amp bench` run of
//   `sins`, `sins-plus`). Target: <= 10 s.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "amp/core/rng.hpp"
#include "amp/nav/sins/motor_schemas.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/sins/sins_plus_parameters.hpp"
#include "amp/nav/sins/sins_run.hpp"

namespace {

using amp::core::Rng;

constexpr int kSensors = 16;
constexpr int kCases = 10;
constexpr int kCaseLength = 20;
constexpr int kWarmUpIntervals = 2000;  // random intervals to fill the library before timing
constexpr double kEagerNewCases = 0.99;  // new_case_threshold: create a case on almost any mismatch

void BM_MotorSchemaStep(benchmark::State& state) {
  std::array<Eigen::Vector2d, kSensors> directions;
  std::array<double, kSensors> readings;
  Rng rng(1);
  for (int i = 0; i < kSensors; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kSensors;
    directions[static_cast<std::size_t>(i)] = Eigen::Vector2d(std::cos(a), std::sin(a));
    readings[static_cast<std::size_t>(i)] = rng.uniform(0.0, 2.0);  // some inside the sphere of influence
  }
  amp::nav::MotorSchemas schemas;
  const amp::nav::SchemaParameters p = amp::nav::SchemaParameters::middle();
  Eigen::Vector2d position(5.0, 5.0);
  const Eigen::Vector2d goal(35.0, 30.0);
  for (auto _ : state) {
    const Eigen::Vector2d v = schemas.velocity(position, goal, readings, directions, p, rng);
    benchmark::DoNotOptimize(v);
    position += 1e-9 * v;  // a dependency between steps, without leaving the spot
  }
  state.counters["readings"] = kSensors;
}

amp::learn::CaseInputs random_inputs(Rng& rng) {
  return {rng.uniform01(), rng.uniform01(), rng.uniform01(), rng.uniform01()};
}

void BM_CaseBasedEndInterval(benchmark::State& state) {
  amp::learn::CaseSettings cases;
  cases.max_cases = kCases;
  cases.case_length = kCaseLength;
  cases.new_case_threshold = kEagerNewCases;
  amp::nav::CaseBasedParameters policy(cases);
  Rng rng(1);
  policy.begin_world(rng);
  for (int i = 0; i < kWarmUpIntervals; ++i) policy.end_interval(random_inputs(rng), rng);
  for (auto _ : state) benchmark::DoNotOptimize(policy.end_interval(random_inputs(rng), rng));
  state.counters["cases"] = policy.cases();
}

void BM_SinsPlusEndInterval(benchmark::State& state) {
  amp::nav::SplittingCaseParameters policy;
  Rng rng(1);
  policy.begin_world(rng);
  for (int i = 0; i < kWarmUpIntervals; ++i) policy.end_interval(random_inputs(rng), rng);
  for (auto _ : state) benchmark::DoNotOptimize(policy.end_interval(random_inputs(rng), rng));
  state.counters["cases"] = policy.cases();
}

template <class Policy>
void BM_Sequence(benchmark::State& state) {
  amp::nav::SinsSettings settings;
  settings.worlds = 200;
  settings.world.clutter = 0.25;
  std::uint64_t seed = 1;
  double solved = 0.0;
  int sequences = 0;
  for (auto _ : state) {
    Policy policy;
    const amp::nav::SequenceOutcome out = amp::nav::run_sequence(policy, settings, seed++);
    solved += amp::nav::estimate(out.worlds, out.worlds.size()).solved_fraction;
    ++sequences;
  }
  state.counters["solved_fraction"] = sequences > 0 ? solved / sequences : 0.0;
  state.counters["worlds"] = settings.worlds;
}

BENCHMARK(BM_MotorSchemaStep)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_CaseBasedEndInterval)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SinsPlusEndInterval)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Sequence<amp::nav::CaseBasedParameters>)
    ->Name("BM_AdaptiveSequence")
    ->Unit(benchmark::kSecond)
    ->Iterations(2);
BENCHMARK(BM_Sequence<amp::nav::SplittingCaseParameters>)
    ->Name("BM_SinsPlusSequence")
    ->Unit(benchmark::kSecond)
    ->Iterations(2);

}  // namespace
