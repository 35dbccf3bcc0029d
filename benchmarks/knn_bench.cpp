// k-nearest-neighbour search: KD-tree (exact: branch and bound on true distances) vs brute force,
// and KD-tree insertion. Read the CPU column: the machine is shared.
#include <memory>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"
#include "amp/roadmap/neighbors/linear_neighbors.hpp"

namespace {

using amp::State;
using namespace amp;

constexpr std::size_t kQueries = 1024;
constexpr std::size_t kK = 10;

std::unique_ptr<core::Space> make_space(int which) {
  switch (which) {
    case 0: return std::make_unique<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
    case 1: return std::make_unique<core::JointSpace>(core::make_se2_space(0, 0, 10, 10, 1.0));
    default: return std::make_unique<core::Se3Space>(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10), 1.0);
  }
}

const char* space_name(int which) { return which == 0 ? "rn2" : which == 1 ? "se2" : "se3"; }

std::vector<State> draw(const core::Space& space, std::size_t n, std::uint64_t seed) {
  core::Rng rng(seed);
  std::vector<State> out(n);
  for (State& s : out) space.sample_uniform(rng, s);
  return out;
}

template <class NN>
void knn(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const std::size_t n = static_cast<std::size_t>(state.range(1));
  NN nn(*space);
  nn.reserve(n);
  const std::vector<State> points = draw(*space, n, 1);
  for (std::size_t i = 0; i < n; ++i) nn.add(i, points[i]);
  const std::vector<State> queries = draw(*space, kQueries, 2);
  std::vector<roadmap::Neighbor> out;
  out.reserve(kK);
  std::size_t q = 0;
  double evaluations = 0.0;
  for (auto _ : state) {
    nn.k_nearest(queries[q++ % kQueries], kK, out);
    benchmark::DoNotOptimize(out.data());
    if constexpr (std::is_same_v<NN, roadmap::KdTreeNeighbors>) {
      evaluations += static_cast<double>(nn.last_distance_evaluations());
    }
  }
  if (evaluations > 0.0) state.counters["true_distances"] = evaluations / static_cast<double>(state.iterations());
  state.SetLabel(space_name(static_cast<int>(state.range(0))));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_KdTreeKnn(benchmark::State& state) { knn<roadmap::KdTreeNeighbors>(state); }
void BM_LinearKnn(benchmark::State& state) { knn<roadmap::LinearNeighbors>(state); }

// Inserting n states one by one into an empty tree; time per state = total / n.
void BM_KdTreeInsert(benchmark::State& state) {
  const auto space = make_space(static_cast<int>(state.range(0)));
  const std::size_t n = static_cast<std::size_t>(state.range(1));
  const std::vector<State> points = draw(*space, n, 1);
  for (auto _ : state) {
    roadmap::KdTreeNeighbors nn(*space);
    nn.reserve(n);
    for (std::size_t i = 0; i < n; ++i) nn.add(i, points[i]);
    benchmark::DoNotOptimize(nn.size());
  }
  state.SetLabel(space_name(static_cast<int>(state.range(0))));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}

}  // namespace

BENCHMARK(BM_KdTreeKnn)->ArgsProduct({{0, 1, 2}, {1000, 100000}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LinearKnn)->ArgsProduct({{2}, {1000, 100000}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KdTreeInsert)->ArgsProduct({{0, 1, 2}, {10000, 100000}})->Unit(benchmark::kMillisecond)->Iterations(1);
