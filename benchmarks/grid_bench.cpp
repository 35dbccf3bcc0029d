// Occupancy-grid worlds: distance transform time and collision-check rates.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/world/distance_transform.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/map_server_loader.hpp"
#include "support/source_tree.hpp"

namespace {

using amp::world::CellState;
using amp::world::GridEnvironment;
using amp::world::GridRobot;
using amp::world::OccupancyGrid;

constexpr std::uint32_t kSeed = 42;
constexpr int kStatesPerBatch = 4096;

std::vector<std::uint8_t> random_sites(int w, int h, double density) {
  std::mt19937 gen(kSeed);
  std::bernoulli_distribution occ(density);
  std::vector<std::uint8_t> site(static_cast<std::size_t>(w) * h);
  for (auto& c : site) c = occ(gen) ? 1 : 0;
  return site;
}

// Exact EDT (Felzenszwalb-Huttenlocher) of a 1000 x 1000 raster; the argument is the density in %.
void BM_DistanceTransform1000(benchmark::State& state) {
  constexpr int kSide = 1000;
  const auto site = random_sites(kSide, kSide, state.range(0) / 100.0);
  amp::world::DistanceTransform dt;
  for (auto _ : state) {
    dt.compute(kSide, kSide, site);
    benchmark::DoNotOptimize(dt.squared_distance(0));
  }
  state.counters["cells/s"] = benchmark::Counter(double(kSide) * kSide, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DistanceTransform1000)->Arg(1)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond);

std::shared_ptr<const OccupancyGrid> office() {
  return std::make_shared<const OccupancyGrid>(
      amp::world::load_map_server(std::filesystem::path(AMP_SOURCE_DIR) / "problems/maps/office.yaml"));
}

template <int kDim>
std::vector<amp::State> random_states(const OccupancyGrid& g) {
  std::mt19937 gen(kSeed);
  const auto e = g.extent();
  std::uniform_real_distribution<double> ux(e.min().x(), e.max().x()), uy(e.min().y(), e.max().y()), ut(-3.14159, 3.14159);
  std::vector<amp::State> states(kStatesPerBatch, amp::State(kDim));
  for (auto& s : states) {
    s[0] = ux(gen);
    s[1] = uy(gen);
    if (kDim == 3) s[2] = ut(gen);
  }
  return states;
}

void run_checks(benchmark::State& state, const GridEnvironment& env, const std::vector<amp::State>& states) {
  amp::core::Counters counters;
  const auto checker = env.make_checker(counters);
  std::size_t i = 0, valid = 0;
  for (auto _ : state) {
    valid += checker->is_valid(states[i]) ? 1 : 0;
    i = (i + 1) % states.size();
  }
  state.counters["checks/s"] = benchmark::Counter(double(counters.cd_calls()), benchmark::Counter::kIsRate);
  state.counters["collision_checks"] = double(counters.cd_calls());
  state.counters["valid%"] = 100.0 * valid / double(counters.cd_calls());
}

// Disc robot (r = 0.25 m) on the bundled office map, uniform random states.
void BM_DiscCheckOffice(benchmark::State& state) {
  const GridEnvironment env(office(), {GridRobot::Kind::kDisc, state.range(0) / 100.0, {}});
  run_checks(state, env, random_states<2>(env.grid()));
}
BENCHMARK(BM_DiscCheckOffice)->Arg(10)->Arg(25)->Arg(50);

// A 0.5 m x 0.3 m rectangle robot (x, y, theta) on the office map.
void BM_PolygonCheckOffice(benchmark::State& state) {
  GridRobot robot;
  robot.kind = GridRobot::Kind::kRigid;
  robot.body.polygons.push_back({{{-0.25, -0.15}, {0.25, -0.15}, {0.25, 0.15}, {-0.25, 0.15}}});
  const GridEnvironment env(office(), robot);
  run_checks(state, env, random_states<3>(env.grid()));
}
BENCHMARK(BM_PolygonCheckOffice);

void BM_DiscClearanceOffice(benchmark::State& state) {
  const GridEnvironment env(office(), {GridRobot::Kind::kDisc, 0.25, {}});
  const auto states = random_states<2>(env.grid());
  amp::core::Counters counters;
  const auto checker = env.make_checker(counters);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(checker->clearance(states[i]).distance);
    i = (i + 1) % states.size();
  }
  state.counters["clearance/s"] = benchmark::Counter(double(counters.clearance_calls()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DiscClearanceOffice);

// The exact distance to the nearest blocked square on the office map, and the same capped at
// range(0) cm (as DWA scores clearance): the capped query skips rows beyond the cap and, far from
// every square, the row scan itself.
void BM_PointDistanceOffice(benchmark::State& state) {
  const amp::world::GridObstacles obstacles(office());
  const auto states = random_states<2>(obstacles.grid());
  const double limit = state.range(0) > 0 ? state.range(0) / 100.0 : std::numeric_limits<double>::infinity();
  std::size_t i = 0;
  for (auto _ : state) {
    const Eigen::Vector2d p(states[i][0], states[i][1]);
    benchmark::DoNotOptimize(obstacles.point_distance_up_to(p, limit));
    i = (i + 1) % states.size();
  }
  state.counters["queries/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PointDistanceOffice)->Arg(0)->Arg(100)->Arg(30);

}  // namespace
