// Cost of the benchmark harness's statistics: the studentized range integrals dominate (REGWQ asks
// for k - 1 quantiles); the tests themselves are linear in the number of runs.
#include <cmath>

#include <benchmark/benchmark.h>

#include "amp/stats/kruskal_wallis.hpp"
#include "amp/stats/levene_test.hpp"
#include "amp/stats/regwq.hpp"
#include "amp/stats/studentized_range.hpp"

namespace {

// Three planners x 240 runs of heavy-tailed run costs, the paper's sample size.
amp::stats::Groups run_costs() {
  amp::stats::Groups g(3);
  for (int gr = 1; gr <= 3; ++gr) {
    for (int i = 0; i < 240; ++i) g[gr - 1].push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + gr) + 0.4 * gr * std::cos(0.7 * i)));
  }
  return g;
}

void BM_StudentizedRangeCdf(benchmark::State& state) {
  const auto k = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(amp::stats::studentized_range_cdf(4.0, k, 717.0));
}
BENCHMARK(BM_StudentizedRangeCdf)->Arg(3)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_StudentizedRangeQuantile(benchmark::State& state) {
  const auto k = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(amp::stats::studentized_range_quantile(0.99, k, 717.0));
}
BENCHMARK(BM_StudentizedRangeQuantile)->Arg(3)->Arg(20)->Unit(benchmark::kMillisecond);

void BM_Regwq3x240(benchmark::State& state) {
  const amp::stats::Groups g = run_costs();
  for (auto _ : state) benchmark::DoNotOptimize(amp::stats::regwq(g, 0.01));
}
BENCHMARK(BM_Regwq3x240)->Unit(benchmark::kMillisecond);

void BM_LeveneAndKruskal3x240(benchmark::State& state) {
  const amp::stats::Groups g = run_costs();
  for (auto _ : state) {
    benchmark::DoNotOptimize(amp::stats::levene_test(g));
    benchmark::DoNotOptimize(amp::stats::kruskal_wallis(g));
  }
}
BENCHMARK(BM_LeveneAndKruskal3x240)->Unit(benchmark::kMicrosecond);

}  // namespace
