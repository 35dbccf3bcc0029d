// SINS case retrieval (Ram & Santamaria 1993, section 2.4): the exhaustive reverse sweep over 10
// cases of length 20 against a full 20-sample history, 10 * 20 alignments. The paper found
// retrieval "very time consuming"; here it runs once per control interval inside the navigation
// loop, comparing about cases * length^2 / 2 samples. Target: <= 20 us.
// BM_CaseCycle adds adapt and learn: one whole control-interval update of the library.
#include <vector>

#include <benchmark/benchmark.h>

#include "amp/core/rng.hpp"
#include "amp/learn/case_library.hpp"

namespace {

using amp::learn::Case;
using amp::learn::CaseHistory;
using amp::learn::CaseLibrary;
using amp::learn::CaseSettings;

constexpr int kCases = 10;
constexpr int kLength = 20;

CaseSettings settings() {
  CaseSettings s;
  s.max_cases = kCases;
  s.case_length = kLength;
  return s;
}

CaseLibrary random_library(amp::core::Rng& rng) {
  std::vector<Case> cases(kCases);
  for (Case& c : cases) {
    c.inputs.resize(kLength);
    c.outputs.resize(kLength);
    for (auto& v : c.inputs) {
      for (double& x : v) x = rng.uniform01();
    }
    for (auto& v : c.outputs) {
      for (double& x : v) x = rng.uniform01();
    }
  }
  return CaseLibrary(settings(), std::move(cases));
}

void push_random(CaseHistory& h, amp::core::Rng& rng) {
  h.push({rng.uniform01(), rng.uniform01(), rng.uniform01(), rng.uniform01()},
         {rng.uniform01(), rng.uniform01(), rng.uniform01(), rng.uniform01()});
}

void BM_CaseRetrieve(benchmark::State& state) {
  amp::core::Rng rng(1);
  const CaseLibrary lib = random_library(rng);
  CaseHistory h(kLength);
  for (int t = 0; t < kLength; ++t) push_random(h, rng);
  for (auto _ : state) benchmark::DoNotOptimize(lib.retrieve(h));
  state.counters["alignments"] = kCases * kLength;
}

void BM_CaseCycle(benchmark::State& state) {
  amp::core::Rng rng(1);
  CaseLibrary lib = random_library(rng);
  CaseHistory h(kLength);
  for (int t = 0; t < kLength; ++t) push_random(h, rng);
  for (auto _ : state) {
    push_random(h, rng);
    const amp::learn::CaseMatch m = lib.retrieve(h);
    benchmark::DoNotOptimize(lib.adapt(m, rng));
    benchmark::DoNotOptimize(lib.learn(m, h));
  }
}

BENCHMARK(BM_CaseRetrieve)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CaseCycle)->Unit(benchmark::kMicrosecond);

}  // namespace
