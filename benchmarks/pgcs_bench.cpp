// PGCS exploration (Vlassis, Papakonstantinou & Tsanakas): 100,000 positions of a random walk in a
// 20 x 20 square, up to 200 clusters (an insertion every 100 steps, a deletion every 5,000), the
// Delaunay triangulation of the centres updated at every step. Target: <= 1 s on one core.
// state.counters: clusters at the end and the mean number of clusters in eq. (2)'s sum per step.
#include <algorithm>
#include <vector>

#include <benchmark/benchmark.h>

#include "amp/core/rng.hpp"
#include "amp/learn/pgcs.hpp"

namespace {

constexpr int kSteps = 100000;
constexpr double kSide = 20.0;
constexpr double kStepSd = 0.1;  // random-walk step, per coordinate

std::vector<Eigen::Vector2d> walk() {
  amp::core::Rng rng(1);
  std::vector<Eigen::Vector2d> xs(kSteps);
  Eigen::Vector2d x(kSide / 2, kSide / 2);
  for (Eigen::Vector2d& v : xs) {
    x += Eigen::Vector2d(rng.normal(0, kStepSd), rng.normal(0, kStepSd));
    x = x.cwiseMax(0.0).cwiseMin(kSide);
    v = x;
  }
  return xs;
}

void run(benchmark::State& state, int index_min_clusters) {
  const std::vector<Eigen::Vector2d> xs = walk();
  amp::learn::PgcsSettings s;
  s.window = 2000;
  s.max_clusters = 200;
  s.insert_every = 100;
  s.delete_every = 5000;
  s.index_min_clusters = index_min_clusters;
  int clusters = 0;
  double visited = 0.0;
  for (auto _ : state) {
    amp::learn::Pgcs p(s);
    long sum = 0;
    for (const Eigen::Vector2d& x : xs) {
      p.step(x);
      sum += p.last_step().visited;
    }
    clusters = p.size();
    visited = static_cast<double>(sum) / kSteps;
    benchmark::DoNotOptimize(p.triangulation().size());
  }
  state.counters["clusters"] = clusters;
  state.counters["visited"] = visited;
}

void BM_PgcsExplore(benchmark::State& state) { run(state, 32); }
void BM_PgcsExploreLinear(benchmark::State& state) { run(state, 1000000); }  // no index: every cluster

BENCHMARK(BM_PgcsExplore)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PgcsExploreLinear)->Unit(benchmark::kMillisecond);

}  // namespace
