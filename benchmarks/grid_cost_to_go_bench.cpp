// Value iteration on an occupancy grid (world::GridCostToGo): the cost-to-goal of every cell of a
// 2000 x 2000 map, with and without Nav2-style obstacle costs. Target: <= 0.5 s on one core.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "amp/world/grid_cost_to_go.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/inflation_cost.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace {

// Random rectangles (walls and boxes) over 15% of a side x side map of 5 cm cells, seeded.
std::shared_ptr<const amp::world::OccupancyGrid> random_map(int side) {
  auto grid = std::make_shared<amp::world::OccupancyGrid>(side, side, 0.05);
  std::mt19937 gen(42);
  std::uniform_int_distribution<int> at(0, side - 1), len(2, side / 20);
  long blocked = 0;
  while (blocked < static_cast<long>(0.15 * side * side)) {
    const int x0 = at(gen), y0 = at(gen), w = len(gen), h = gen() % 2 == 0 ? 2 : len(gen);
    for (int y = y0; y < std::min(side, y0 + h); ++y) {
      for (int x = x0; x < std::min(side, x0 + w); ++x) {
        if (grid->state(x, y) == amp::world::CellState::kFree) ++blocked;
        grid->set_state(x, y, amp::world::CellState::kOccupied);
      }
    }
  }
  return grid;
}

void BM_ValueIteration2000(benchmark::State& state) {
  const amp::world::GridObstacles obstacles(random_map(2000));
  amp::world::InflationSettings s;
  s.inscribed_radius = 0.27;  // the paper's 54 cm robot
  if (state.range(0) != 0) s.inflation_radius = 0.8;
  amp::world::GridCostToGo dp(amp::world::inflate(obstacles, s));
  int goal = 0;
  while (!dp.free(goal % 2000, goal / 2000)) goal += 2001;
  for (auto _ : state) {
    dp.compute(goal);
    benchmark::DoNotOptimize(dp.distance(goal));
  }
  long reached = 0;
  for (double d : dp.distances()) reached += d < amp::world::GridCostToGo::kUnreachable ? 1 : 0;
  state.counters["reached"] = static_cast<double>(reached);
}
BENCHMARK(BM_ValueIteration2000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
