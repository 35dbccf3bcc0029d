#include "amp/roadmap/trees/rrt_connect.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/core/joint_space.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

constexpr std::size_t kNodeLimit = 50000;  // the bundled problems' default
constexpr double kNoTimeLimit = 1e6;  // the node limit ends every test run, never the clock

struct Outcome {
  PlanResult result;
  std::uint64_t cd_calls = 0;
  std::uint64_t clearance_calls = 0;
};

Outcome run_rrt(const world::Problem& p, std::uint64_t seed, RrtConnectSettings settings = {},
                core::EdgeCheckMode mode = core::EdgeCheckMode::kDiscrete, std::size_t node_limit = kNodeLimit,
                double time_limit = kNoTimeLimit) {
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds, mode};
  core::Rng rng(seed);
  const core::StopCondition stop(time_limit, node_limit);
  RrtConnect planner(settings);
  Outcome o{planner.plan(ctx, stop, rng), 0, 0};
  o.cd_calls = counters.cd_calls();
  o.clearance_calls = counters.clearance_calls();
  return o;
}

const world::Problem& bundled(const std::string& name) {
  // Loaded once per test executable (meshes and grids take a moment); problems are immutable.
  static std::map<std::string, world::Problem> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    it = cache.emplace(name, world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/" + name)).first;
  }
  return it->second;
}

// Every seed appears in the path, in order.
void expect_through_seeds(const world::Problem& p, const std::vector<State>& path) {
  auto from = path.begin();
  for (const State& s : p.seeds) {
    from = std::find(from, path.end(), s);
    ASSERT_NE(from, path.end()) << p.name << ": a seed is missing or out of order";
  }
}

void expect_solved_and_valid(const world::Problem& p, const Outcome& o, int refinement = 4) {
  ASSERT_EQ(o.result.status, core::PlanStatus::kSolved) << p.name;
  amp::test::expect_valid_path(p, o.result.path, refinement);
  expect_through_seeds(p, o.result.path);
  ASSERT_NE(o.result.roadmap, nullptr);
  EXPECT_EQ(o.result.nodes, o.result.roadmap->vertex_count());
  EXPECT_EQ(o.result.edges, o.result.roadmap->edge_count());
  EXPECT_EQ(o.result.components, 1u);  // a solved run joins every tree
  EXPECT_EQ(o.result.edges, o.result.nodes - 1);  // trees and their meeting edges: still a tree
}

// The other bundled problems (hook, linkage, walls3d, scara-wicket) are solved in
// tests/problems/bundled_problems_test.cpp, which the sanitizer run leaves out.
TEST(RrtConnect, SolvesTheBundledMaze) {
  const world::Problem& p = bundled("maze.yaml");
  const Outcome o = run_rrt(p, 1);
  expect_solved_and_valid(p, o);
  EXPECT_EQ(o.result.extra.at("legs_solved"), 1.0);
  EXPECT_TRUE(o.result.extra.count("certify_refused"));
  EXPECT_TRUE(o.result.extra.count("certified_segments"));
}

TEST(RrtConnect, SameSeedSameResultDifferentSeedDifferentResult) {
  const world::Problem& p = bundled("l-tunnel.yaml");
  const Outcome a = run_rrt(p, 42), b = run_rrt(p, 42), c = run_rrt(p, 43);
  ASSERT_EQ(a.result.status, core::PlanStatus::kSolved);
  ASSERT_EQ(a.result.path.size(), b.result.path.size());
  for (std::size_t i = 0; i < a.result.path.size(); ++i) {
    for (int j = 0; j < a.result.path[i].size(); ++j) EXPECT_EQ(a.result.path[i][j], b.result.path[i][j]);  // bit for bit
  }
  EXPECT_EQ(a.cd_calls, b.cd_calls);
  EXPECT_EQ(a.result.nodes, b.result.nodes);
  EXPECT_EQ(a.result.extra, b.result.extra);
  EXPECT_TRUE(a.result.path != c.result.path || a.cd_calls != c.cd_calls);
}

TEST(RrtConnect, ConnectsEverySeedInOrder) {
  // The bundled puzzle's three seeds need the 6-DOF puzzle solved twice; the point world with a
  // third seed across the wall exercises the same leg-by-leg code in milliseconds.
  world::Problem p = test::point_problem(true);
  p.seeds = {test::state2(1, 1), test::state2(9, 9), test::state2(1, 9), test::state2(9, 1)};
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Outcome o = run_rrt(p, seed);
    expect_solved_and_valid(p, o);
    EXPECT_EQ(o.result.extra.at("legs_solved"), 3.0);
    EXPECT_EQ(o.result.path.front(), p.seeds.front());
    EXPECT_EQ(o.result.path.back(), p.seeds.back());
  }
}

TEST(RrtConnect, ConnectsEverySeedOfABundledProblemInOrder) {
  // L-Tunnel with a third and fourth seed: a state halfway along a first solution, and the start
  // again, so the last leg runs back through the tunnel.
  world::Problem p = bundled("l-tunnel.yaml");
  const Outcome first = run_rrt(p, 4);
  ASSERT_EQ(first.result.status, core::PlanStatus::kSolved);
  const State middle = first.result.path[first.result.path.size() / 2];
  p.seeds = {p.seeds.front(), middle, p.seeds.back(), p.seeds.front()};
  const Outcome o = run_rrt(p, 4);
  expect_solved_and_valid(p, o);
  EXPECT_EQ(o.result.extra.at("legs_solved"), 3.0);
}

TEST(RrtConnect, SingleSeedIsItsOwnPath) {
  world::Problem p = test::point_problem(true);
  p.seeds = {test::state2(1, 1)};
  const Outcome o = run_rrt(p, 1);
  EXPECT_EQ(o.result.status, core::PlanStatus::kSolved);
  ASSERT_EQ(o.result.path.size(), 1u);
  EXPECT_EQ(o.result.nodes, 1u);
}

TEST(RrtConnect, NodeLimitOnAnUnsolvableProblem) {
  const world::Problem p = test::point_problem(false);
  const Outcome o = run_rrt(p, 1, {}, core::EdgeCheckMode::kDiscrete, 300);
  EXPECT_EQ(o.result.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(o.result.nodes, 300u);  // CONNECT's inner steps poll the limit too: never overshot
  EXPECT_TRUE(o.result.path.empty());
  EXPECT_EQ(o.result.components, 2u);  // the two trees
  EXPECT_EQ(o.result.edges, 298u);
}

TEST(RrtConnect, NodeLimitOnTheLaterLegOfAMultiSeedProblem) {
  world::Problem p = test::point_problem(false);
  p.seeds = {test::state2(1, 1), test::state2(1, 9), test::state2(9, 9)};  // leg 1 crosses the wall
  const Outcome o = run_rrt(p, 1, {}, core::EdgeCheckMode::kDiscrete, 400);
  EXPECT_EQ(o.result.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(o.result.extra.at("legs_solved"), 1.0);
  EXPECT_EQ(o.result.nodes, 400u);
  EXPECT_TRUE(o.result.path.empty());
  EXPECT_EQ(o.result.components, 2u);  // leg 0's trees and leg 1's start tree, and leg 1's goal tree
}

TEST(RrtConnect, TimeLimitOnAnUnsolvableProblem) {
  const world::Problem p = test::point_problem(false);
  const Outcome o = run_rrt(p, 1, {}, core::EdgeCheckMode::kDiscrete, static_cast<std::size_t>(-1), 0.02);
  EXPECT_EQ(o.result.status, core::PlanStatus::kTimeout);
  EXPECT_TRUE(o.result.path.empty());
}

TEST(RrtConnect, LimitsOnABundledProblemAreHonouredAndReported) {
  const world::Problem& p = bundled("maze.yaml");  // needs tens of thousands of nodes
  const Outcome n = run_rrt(p, 1, {}, core::EdgeCheckMode::kDiscrete, 500);
  EXPECT_EQ(n.result.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(n.result.nodes, 500u);
  EXPECT_TRUE(n.result.path.empty());
  const Outcome t = run_rrt(p, 1, {}, core::EdgeCheckMode::kDiscrete, static_cast<std::size_t>(-1), 0.05);
  EXPECT_EQ(t.result.status, core::PlanStatus::kTimeout);
  EXPECT_TRUE(t.result.path.empty());
  EXPECT_GT(t.result.nodes, 0u);
}

TEST(RrtConnect, RangeDefaultsToAFifthOfTheExtentAndBoundsEveryEdge) {
  const world::Problem& p = bundled("walls.yaml");
  EXPECT_EQ(effective_range({}, *p.space), 0.2 * p.space->maximum_extent());
  EXPECT_EQ(effective_range({5.0}, *p.space), 5.0);
  for (double range : {0.0, 5.0}) {
    const Outcome o = run_rrt(p, 7, {range});
    ASSERT_EQ(o.result.status, core::PlanStatus::kSolved);
    const double expected = effective_range({range}, *p.space);
    EXPECT_EQ(o.result.extra.at("range"), expected);
    const Roadmap& forest = *o.result.roadmap;
    for (VertexId v = 0; v < forest.vertex_count(); ++v) {
      for (const Edge& e : forest.edges(v)) EXPECT_LE(e.cost, expected * (1 + 1e-12));
    }
  }
}

TEST(RrtConnect, BadRangeIsAParameterError) {
  EXPECT_THROW(builtin_planners().make("rrt-connect", {{"range", -1.0}}), ParameterError);
  EXPECT_THROW(RrtConnect(RrtConnectSettings{-0.5}), ParameterError);
  const auto planner = builtin_planners().make("rrt-connect", {{"range", 2.5}});
  const auto* rrt = dynamic_cast<const RrtConnect*>(planner.get());
  ASSERT_NE(rrt, nullptr);
  EXPECT_EQ(rrt->settings().range, 2.5);
  EXPECT_EQ(builtin_planners().info("rrt-connect").params.front().name, "range");
}

TEST(RrtConnect, CertifiedModeCertifiesEveryEdge) {
  for (const char* name : {"walls.yaml", "linkage.yaml"}) {
    const world::Problem& p = bundled(name);
    const Outcome o = run_rrt(p, 3, {}, core::EdgeCheckMode::kCertified);
    expect_solved_and_valid(p, o);
    // Every forest edge was certified when it was made; nothing is left to refuse at the meeting.
    EXPECT_GE(o.result.extra.at("certified_segments"), static_cast<double>(o.result.edges)) << name;
    EXPECT_EQ(o.result.extra.at("certify_refused"), 0.0) << name;
    EXPECT_GT(o.clearance_calls, 0u) << name;
  }
}

// A wall far thinner than the edge-check step: discrete checks jump over it, certification does
// not. The path found must still go through the gap, after refused edges were cut.
world::Problem thin_wall_problem() {
  world::Problem p = test::point_problem(true);
  auto space = std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
  space->set_resolution(1.0);
  p.space = space;
  p.environment = std::make_shared<test::BoxEnvironment>(
      std::vector<test::Box>{{4.99, 0.0, 5.01, 4.0}, {4.99, 6.0, 5.01, 10.0}}, test::RobotKind::kPoint);
  return p;
}

TEST(RrtConnect, DiscreteModeCutsRefusedEdgesAndStillReturnsACertifiedPath) {
  const world::Problem p = thin_wall_problem();
  double refused = 0, cut = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Outcome o = run_rrt(p, seed);
    expect_solved_and_valid(p, o, 400);  // steps of 0.0025: finer than the wall
    refused += o.result.extra.at("certify_refused");
    cut += o.result.extra.at("nodes_cut");
  }
  EXPECT_GT(refused, 0.0);  // the wall was jumped and caught
  EXPECT_GT(cut, 0.0);
}

TEST(RrtConnect, CertifiedModeNeverJumpsTheThinWall) {
  const world::Problem p = thin_wall_problem();
  const Outcome o = run_rrt(p, 2, {}, core::EdgeCheckMode::kCertified);
  expect_solved_and_valid(p, o, 400);
  EXPECT_EQ(o.result.extra.at("certify_refused"), 0.0);
}

}  // namespace
}  // namespace amp::roadmap
