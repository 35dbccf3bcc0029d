// Region identification's clustering step (the UAS paper, step 3; docs/uas.md) on a 400-point 3-D training set:
// four Gaussian blobs (sd 1) of 100 points at the vertices of a tetrahedron 10 from its centre,
// standardised as UAS standardises its features. Targets: k-means over c = 1..10 with 10 restarts and
// Ward < 50 ms; PG-means < 500 ms; auto (all three and their silhouettes) reported. state.counters["clusters"] reports the c chosen.
#include <cmath>

#include <benchmark/benchmark.h>

#include "amp/core/rng.hpp"
#include "amp/learn/clusterer_choice.hpp"
#include "amp/learn/kmeans.hpp"
#include "amp/learn/pg_means.hpp"
#include "amp/learn/standardize.hpp"
#include "amp/learn/ward.hpp"

namespace {

constexpr int kPerBlob = 100;
constexpr double kDistance = 10.0;

Eigen::MatrixXd training_set() {
  const double t = kDistance / std::sqrt(3.0);
  const double centres[4][3] = {{t, t, t}, {t, -t, -t}, {-t, t, -t}, {-t, -t, t}};
  amp::core::Rng rng(2009);
  Eigen::MatrixXd x(4 * kPerBlob, 3);
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i < kPerBlob; ++i) {
      for (int j = 0; j < 3; ++j) x(c * kPerBlob + i, j) = centres[c][j] + rng.normal();
    }
  }
  return amp::learn::standardize(x);
}

void run(benchmark::State& state, const amp::learn::Clusterer& method) {
  const Eigen::MatrixXd x = training_set();
  int c = 0;
  for (auto _ : state) {
    amp::core::Rng rng(7);
    const amp::learn::Clustering out = method.cluster(x, rng);
    c = out.c;
    benchmark::DoNotOptimize(out.labels.data());
  }
  state.counters["clusters"] = c;
  state.counters["points"] = static_cast<double>(x.rows());
}

void BM_KMeans(benchmark::State& state) { run(state, amp::learn::KMeans()); }
void BM_Ward(benchmark::State& state) { run(state, amp::learn::WardClustering()); }
void BM_PgMeans(benchmark::State& state) { run(state, amp::learn::PgMeans()); }
// UAS's automatic choice: the three methods plus a silhouette (O(n^2)) each.
void BM_Auto(benchmark::State& state) { run(state, amp::learn::AutoClusterer()); }

BENCHMARK(BM_KMeans)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Ward)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PgMeans)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Auto)->Unit(benchmark::kMillisecond);

}  // namespace
