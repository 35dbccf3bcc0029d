// Property tests of every planner on 2,000 random planar problems (issue 17): polygon and circle
// worlds with point, disc, rigid, arm and linkage robots, and MovingAI map worlds (every
// kMapEvery-th case, grid-dp's). Each case is drawn from its own seed, written as a YAML file and
// loaded as `amp plan` loads it; planners take turns and draw small parameters. For every run:
//  - it ends within its time limit + 5 % + 50 ms and never holds more nodes than its node limit;
//  - a solved path starts at the start, ends at the goal, and is certified collision-free by the
//    test's own conservative advancement (exact 2-D distances from the file's shapes, and a bound on
//    how far any robot point moves, both computed here);
//  - a run whose result depends on its seed alone gives the same record and path when it is run
//    again on two threads at once.
// Eight shards of 250 cases, so that ctest -j2 spreads them. A failing shard leaves its problem
// files in place; the message names the file and the `amp plan` arguments that repeat the run.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/bench/bench_runner.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/problem.hpp"
#include "support/exact_geometry.hpp"
#include "support/planner_runs.hpp"
#include "support/random_problems.hpp"
#include "support/sanitizer_build.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;
using test::RobotKind;

constexpr std::uint64_t kMasterSeed = 0x17'0002'0001ULL;
constexpr int kCases = 2000;
constexpr int kShards = 8;
constexpr int kMapEvery = 8;
// Conservative advancement steps allowed per path before the certificate gives up.
constexpr long kCertifyBudget = 2'000'000;

// How far any point of the robot moves per unit of t along the straight segment a -> b.
double motion_bound(const test::RobotModel& r, const State& a, const State& b) {
  const auto d = [&](int i) { return std::abs(r.coordinate_kind(i) == 1 ? test::wrap(b[i] - a[i]) : b[i] - a[i]); };
  // reach(j): farthest robot point beyond joint j from it (links j.. of a chain).
  const auto reach = [&](std::size_t j) {
    double best = 0.0, along = 0.0;
    for (std::size_t k = j; k < r.links.size(); ++k) {
      const double h = 0.5 * r.links[k].width;
      best = std::max(best, along + std::hypot(r.links[k].length + h, h));
      along += r.links[k].length;
    }
    return best;
  };
  switch (r.kind) {
    case RobotKind::kPoint:
    case RobotKind::kDisc:
      return std::hypot(d(0), d(1));
    case RobotKind::kRigid: {
      double radius = 0.0;
      for (const test::Poly& p : r.polygons) {
        for (const test::Vec2& v : p) radius = std::max(radius, v.norm());
      }
      for (const test::Disc& c : r.discs) radius = std::max(radius, c.c.norm() + c.r);
      return std::hypot(d(0), d(1)) + radius * d(2);
    }
    case RobotKind::kArm: {
      double m = 0.0;
      for (std::size_t j = 0; j < r.links.size(); ++j) m += reach(j) * d(static_cast<int>(j));
      return m;
    }
    case RobotKind::kLinkage: {
      double m = std::hypot(d(0), d(1));
      for (std::size_t j = 0; j < r.links.size(); ++j) m += reach(j) * d(static_cast<int>(j + 2));
      return m;
    }
  }
  return test::kInf;
}

// The space's straight line as the problem format defines it: wrapping angles the short way round.
State interpolate(const test::RobotModel& r, const State& a, const State& b, double t) {
  State s = a;
  for (int i = 0; i < a.size(); ++i) s[i] += t * (r.coordinate_kind(i) == 1 ? test::wrap(b[i] - a[i]) : b[i] - a[i]);
  return s;
}

double state_gap(const test::RobotModel& r, const State& a, const State& b) {
  if (a.size() != b.size()) return test::kInf;
  double g = 0.0;
  for (int i = 0; i < a.size(); ++i) g = std::max(g, std::abs(r.coordinate_kind(i) == 1 ? test::wrap(b[i] - a[i]) : b[i] - a[i]));
  return g;
}

// "" when every segment is certified: from t = 0, the clearance c at t keeps every robot point
// away from what it could hit while it moves less than c, so t may advance by c / motion_bound.
std::string certify(const test::PlanarModel& m, const std::vector<State>& path) {
  test::Placed placed;
  const double floor = 1e-12 * (m.bounds.hi - m.bounds.lo).maxCoeff();
  long budget = kCertifyBudget;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double speed = motion_bound(m.robot, path[i - 1], path[i]);
    for (double t = 0.0;;) {
      const double c = test::clearance(m, interpolate(m.robot, path[i - 1], path[i], t), placed);
      if (!(c > floor)) {
        return "segment " + std::to_string(i) + " of " + std::to_string(path.size() - 1) + " at t = " + test::num(t) +
               ": clearance " + test::num(c);
      }
      if (t >= 1.0) break;
      if (--budget < 0) return "not certified within " + std::to_string(kCertifyBudget) + " steps (segment " + std::to_string(i) + ")";
      t = speed > 0.0 ? std::min(1.0, t + 0.999 * c / speed) : 1.0;
    }
  }
  return "";
}

using Case = test::PlannerCase<test::PlanarModel>;

bool is_map_case(int index) { return index % kMapEvery == kMapEvery - 1; }

// Planners take turns; a map case with a point or disc robot goes to grid-dp every third time.
std::string pick_planner(int index, const test::PlanarModel& m) {
  static const std::vector<std::string> others = test::any_world_planners();
  const bool grid_robot = m.robot.kind == RobotKind::kPoint || m.robot.kind == RobotKind::kDisc;
  if (is_map_case(index)) {
    const int k = index / kMapEvery;
    return grid_robot && k % 3 == 0 ? "grid-dp" : others[static_cast<std::size_t>(k) % others.size()];
  }
  return others[static_cast<std::size_t>(index) % others.size()];
}

Case make_case(int index, const fs::path& root) {
  Case c;
  c.index = index;
  core::Rng rng(core::derive_seed(kMasterSeed, static_cast<std::uint64_t>(index)));
  test::PlanarOptions o;
  o.map = is_map_case(index);
  c.model = test::random_planar(rng.next_u64(), o);
  const fs::path dir = root / ("case-" + std::to_string(index));
  fs::create_directories(dir);
  c.file = dir / "problem.yaml";
  std::ofstream(c.file) << "name: case-" << index << "\n" << c.model.yaml;
  if (o.map) std::ofstream(dir / "map.map") << c.model.map_text;
  c.problem = world::load_problem(c.file);
  c.planner = pick_planner(index, c.model);
  c.draw_run(rng, 300);
  return c;
}

// A solved run's path, besides the limits that run_shard checks.
void expect_solved_path(const Case& c, const test::TimedRun& r) {
  const std::vector<State>& path = r.out.path;
  ASSERT_GE(path.size(), 2u) << c.describe();
  EXPECT_EQ(r.out.record.path_states, path.size()) << c.describe();
  const double tol = 1e-9 * (c.model.bounds.hi - c.model.bounds.lo).maxCoeff();
  EXPECT_LE(state_gap(c.model.robot, path.front(), c.model.start), tol) << "path does not start at the start\n" << c.describe();
  EXPECT_LE(state_gap(c.model.robot, path.back(), c.model.goal), tol) << "path does not end at the goal\n" << c.describe();
  const std::string why = certify(c.model, path);
  EXPECT_EQ(why, "") << "solved path not certified: " << why << "\n" << c.describe();
}

class PlanarProperties : public ::testing::TestWithParam<int> {};

TEST_P(PlanarProperties, RunsKeepTheirLimitsAndSolvedPathsAreCertifiedAndThreadIndependent) {
  const int shard = GetParam(), per_shard = kCases / kShards;
  test::TempDir dir("planar-" + std::to_string(shard));
  std::vector<Case> cases;
  for (int i = shard * per_shard; i < shard * per_shard + test::case_share(per_shard); ++i) cases.push_back(make_case(i, dir.path()));
  test::run_shard("shard " + std::to_string(shard), cases, expect_solved_path);
}

// The certificate is no rubber stamp: on the straight line from start to goal of the first 200
// cases, wherever a dense sampling finds the robot overlapping something, it refuses the line.
TEST(PlanarCertificate, RefusesEveryStraightLineASamplingFindsInCollision) {
  int refused = 0;
  test::Placed placed;
  for (int i = 0; i < 200; ++i) {
    core::Rng rng(core::derive_seed(kMasterSeed, static_cast<std::uint64_t>(i)));
    test::PlanarOptions o;
    o.map = is_map_case(i);
    const test::PlanarModel m = test::random_planar(rng.next_u64(), o);
    bool hit = false;
    for (int k = 0; k <= 2000 && !hit; ++k) hit = test::clearance(m, interpolate(m.robot, m.start, m.goal, k / 2000.0), placed) <= 0.0;
    const std::string why = certify(m, {m.start, m.goal});
    if (hit) {
      EXPECT_NE(why, "") << "case " << i << ": a colliding line was certified\n" << m.yaml;
    }
    refused += why.empty() ? 0 : 1;
  }
  EXPECT_GT(refused, 20);
}

// The same experiment through the bench runner (amp bench -j1 and -j2): runs.csv equal but for the
// wall-time column. Node limits end every run; the time limit never binds.
TEST(PlanarBench, RunsCsvIsTheSameOnOneAndTwoThreads) {
  test::TempDir dir("planar-bench");
  std::ostringstream e;
  e << "name: property\nseed: 17\nruns: 2\ntime_limit: 60\nnode_limit: 120\nproblems:\n";
  for (int i = 0; i < 4; ++i) {
    test::PlanarOptions o;
    o.resolution = 0.01;
    std::string name = "p";
    name += std::to_string(i);
    std::ofstream(dir.path() / (name + ".yaml")) << "name: " << name << "\n"
                                                << test::random_planar(core::derive_seed(kMasterSeed + 1, i), o).yaml;
    e << "  - " << name << ".yaml\n";
  }
  e << "planners:\n";
  for (const std::string& p : builtin_planners().names()) {
    if (p != "grid-dp") e << "  - " << p << "\n";
  }
  e << "  - {name: prm-drawn, planner: prm, draw: {k: [2, 7, 12], lazy: [true, false]}}\n";
  std::ofstream(dir.path() / "experiment.yaml") << e.str();
  const auto csv_without_time = [&](int threads) {
    bench::BenchOptions options;
    options.out_dir = dir.path() / ("out-" + std::to_string(threads));
    options.threads = threads;
    bench::run_experiment(bench::load_experiment(dir.path() / "experiment.yaml"), options);
    std::ifstream in(options.out_dir / "runs.csv");
    std::string line, out;
    int time_column = -1;
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::stringstream ss(line);
      for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
      if (time_column < 0) time_column = static_cast<int>(std::find(cells.begin(), cells.end(), "wall_time_s") - cells.begin());
      if (time_column < static_cast<int>(cells.size())) cells.erase(cells.begin() + time_column);
      for (const std::string& c : cells) out += c + ",";
      out += "\n";
    }
    return out;
  };
  const std::string one = csv_without_time(1), two = csv_without_time(2);
  EXPECT_GT(std::count(one.begin(), one.end(), '\n'), 40);
  EXPECT_EQ(one, two);
}

INSTANTIATE_TEST_SUITE_P(Shards, PlanarProperties, ::testing::Range(0, kShards));

}  // namespace
}  // namespace amp::roadmap
