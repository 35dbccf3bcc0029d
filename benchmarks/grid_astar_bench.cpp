// Cost of the A* grid local planner per cell, apart from the validity checks: a search that is
// stopped after exactly 10,000 checked cells, against a checker that only tests one coordinate
// (a wall across the space, so the search never meets). Target (docs/run-cost-variance.md): <= 5 ms per 10,000 cells.
#include <benchmark/benchmark.h>

#include <memory>
#include <numbers>

#include "amp/core/counters.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/roadmap/competence/grid_astar_planner.hpp"

namespace {

using amp::State;

class Wall final : public amp::world::ValidityChecker {
 public:
  using ValidityChecker::ValidityChecker;

 private:
  bool check(const State& s) const override { return s[0] < 0.45 || s[0] > 0.55; }
  amp::world::Clearance compute_clearance(const State&) const override { return {}; }
  // Not certified here: the benchmark times the search alone.
  double compute_free_radius(const State&) const override { return 0.0; }
  double compute_motion_bound(const State&, const State&) const override { return 1.0; }
};

void search_10k(benchmark::State& bench, const amp::core::Space& space, int steps, const State& a, const State& b) {
  amp::core::Counters counters;
  Wall wall(counters);
  amp::roadmap::GridAStarSettings g;
  g.steps = steps;
  g.max_cells = 10000;
  amp::roadmap::GridAStarPlanner astar(space, wall, g);
  for (auto _ : bench) {
    benchmark::DoNotOptimize(astar.connect(a, b));
    if (astar.last().cells_checked != 10000) bench.SkipWithError("search did not reach 10,000 cells");
  }
  bench.counters["cells"] = static_cast<double>(astar.last().cells_checked);
  bench.counters["ns_per_cell"] = benchmark::Counter(10000.0 * static_cast<double>(bench.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_GridAStar5Dof(benchmark::State& bench) {
  std::vector<amp::core::Joint> joints;
  for (const char* name : {"q0", "q1", "q2", "q3", "q4"}) {
    joints.push_back({name, amp::core::JointKind::kLinear, 0.0, 1.0, 1.0});
  }
  const amp::core::JointSpace space("linkage", joints);
  State a(5), b(5);
  a << 0.2, 0.5, 0.5, 0.5, 0.5;
  b << 0.8, 0.5, 0.5, 0.5, 0.5;
  search_10k(bench, space, 128, a, b);
}
BENCHMARK(BM_GridAStar5Dof)->Unit(benchmark::kMillisecond);

void BM_GridAStarSe3(benchmark::State& bench) {
  const amp::core::Se3Space space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 0.5);
  const State a = amp::core::Se3Space::make_state(Eigen::Vector3d(0.2, 0.5, 0.5), Eigen::Quaterniond::Identity());
  const State b = amp::core::Se3Space::make_state(Eigen::Vector3d(0.8, 0.5, 0.5), Eigen::Quaterniond::Identity());
  search_10k(bench, space, 512, a, b);
}
BENCHMARK(BM_GridAStarSe3)->Unit(benchmark::kMillisecond);

}  // namespace
