// Validity checks per second of the planar checker: an L-shaped SE2 robot (two rectangles) among
// random star-shaped polygons, about 500 or 5,000 obstacle edges.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "amp/core/rng.hpp"
#include "amp/world/planar_checker.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace {

using amp::world::Polygon;
using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;
constexpr int kStates = 4096;  // pre-drawn states, cycled, so sampling is not timed

// Random star-shaped polygons (3-12 vertices) until `edges` edges, centres uniform in [0, size]^2.
std::shared_ptr<const amp::world::PlanarWorld> make_world(int edges, double size, std::uint64_t seed) {
  amp::core::Rng rng(seed);
  amp::world::Shapes2d s;
  int count = 0;
  while (count < edges) {
    const V c(rng.uniform(0, size), rng.uniform(0, size));
    const double r = rng.uniform(0.5, 2.5);
    const int n = 3 + static_cast<int>(rng.uniform_index(10));
    std::vector<double> a(n);
    for (double& x : a) x = rng.uniform(0, 2 * kPi);
    std::sort(a.begin(), a.end());
    Polygon p;
    for (double t : a) p.vertices.push_back(c + rng.uniform(0.3 * r, r) * V(std::cos(t), std::sin(t)));
    if (std::abs(amp::world::signed_area(p.vertices)) < 1e-2 || !amp::world::is_simple(p.vertices)) continue;
    count += n;
    s.polygons.push_back(std::move(p));
  }
  return std::make_shared<const amp::world::PlanarWorld>(std::move(s), Eigen::AlignedBox2d(V(0, 0), V(size, size)));
}

amp::world::PlanarRobot l_robot() {
  const Polygon bar{{{-1, -0.15}, {1, -0.15}, {1, 0.15}, {-1, 0.15}}};
  const Polygon foot{{{-1, 0.15}, {-0.7, 0.15}, {-0.7, 1}, {-1, 1}}};
  return amp::world::PlanarRobot::rigid({{bar, foot}, {}});
}

void run(benchmark::State& state, int edges, double size) {
  const auto world = make_world(edges, size, 42);
  amp::core::Counters counters;
  amp::world::PlanarChecker checker(world, l_robot(), counters);
  amp::core::Rng rng(7);
  std::vector<amp::State> states(kStates, amp::State(3));
  for (auto& s : states) s << rng.uniform(0, size), rng.uniform(0, size), rng.uniform(-kPi, kPi);
  std::size_t i = 0, valid = 0;
  for (auto _ : state) {
    const bool v = checker.is_valid(states[i]);
    valid += v;
    benchmark::DoNotOptimize(v);
    i = (i + 1) % kStates;
  }
  state.counters["checks"] = benchmark::Counter(static_cast<double>(counters.cd_calls()), benchmark::Counter::kIsRate);
  state.counters["valid_fraction"] = static_cast<double>(valid) / static_cast<double>(state.iterations());
  state.counters["edges"] = static_cast<double>(world->edges().size());
  state.counters["grid_cells"] = static_cast<double>(world->grid().nx() * world->grid().ny());
}

void BM_PlanarCheck500Edges(benchmark::State& state) { run(state, 500, 50.0); }
// Ten times the edges over ten times the area: the same density, a bigger world.
void BM_PlanarCheck5000EdgesSameDensity(benchmark::State& state) { run(state, 5000, 50.0 * std::sqrt(10.0)); }
// Ten times the edges in the same area: a cluttered world.
void BM_PlanarCheck5000EdgesDense(benchmark::State& state) { run(state, 5000, 50.0); }

void BM_PlanarClearance500Edges(benchmark::State& state) {
  const auto world = make_world(500, 50.0, 42);
  amp::core::Counters counters;
  amp::world::PlanarChecker checker(world, l_robot(), counters);
  amp::core::Rng rng(7);
  std::vector<amp::State> states(kStates, amp::State(3));
  for (auto& s : states) s << rng.uniform(0, 50.0), rng.uniform(0, 50.0), rng.uniform(-kPi, kPi);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(checker.clearance(states[i]).distance);
    i = (i + 1) % kStates;
  }
  state.counters["queries"] =
      benchmark::Counter(static_cast<double>(counters.clearance_calls()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(BM_PlanarCheck500Edges);
BENCHMARK(BM_PlanarCheck5000EdgesSameDensity);
BENCHMARK(BM_PlanarCheck5000EdgesDense);
BENCHMARK(BM_PlanarClearance500Edges);
