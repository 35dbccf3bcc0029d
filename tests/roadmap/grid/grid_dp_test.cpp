#include "amp/roadmap/grid/grid_dp.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <unistd.h>

#include "support/path_checks.hpp"

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;
const double kSqrt2 = std::sqrt(2.0);

// A MovingAI map (rows top first: '.' free, '@' blocked) and a problem on it in a fresh directory.
world::Problem map_problem(const std::string& name, const std::vector<std::string>& rows, const std::string& robot,
                           const std::string& start, const std::string& goal) {
  const fs::path dir = fs::temp_directory_path() / ("amp_grid_dp_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream map(dir / (name + ".map"));
    map << "type octile\nheight " << rows.size() << "\nwidth " << rows.front().size() << "\nmap\n";
    for (const auto& r : rows) map << r << "\n";
  }
  {
    std::ofstream yaml(dir / (name + ".yaml"));
    yaml << "name: " << name << "\nworld:\n  map: " << name << ".map\nrobot: " << robot << "\nstart: " << start
         << "\ngoal: " << goal << "\n";
  }
  return world::load_problem(dir / (name + ".yaml"));
}

PlanResult run(const world::Problem& p, GridDpSettings settings = {}, std::uint64_t seed = 1) {
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(seed);
  const core::StopCondition stop(1e6, 1000000);
  return GridDp(settings).plan(ctx, stop, rng);
}

double length(const world::Problem& p, const std::vector<State>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) sum += p.space->distance(path[i - 1], path[i]);
  return sum;
}

void expect_octile(const world::Problem& p, double expected) {
  const PlanResult r = run(p);
  ASSERT_EQ(r.status, core::PlanStatus::kSolved) << p.name;
  amp::test::expect_valid_path(p, r.path, 4);
  EXPECT_NEAR(length(p, r.path), expected, 1e-9 * expected) << p.name;
  EXPECT_NEAR(r.extra.at("grid_cost"), expected, 1e-9 * expected) << p.name;
  EXPECT_EQ(r.extra.at("refused_segments"), 0.0);
}

// Point robots between cell centres: the optimal octile lengths, by hand.
TEST(GridDp, PointRobotPathsAreTheOptimalOctileLengths) {
  // Open 10 x 6 room, corner to corner: 5 diagonals and 4 straight steps.
  expect_octile(map_problem("open", std::vector<std::string>(6, ".........."), "{type: point}", "[0.5, 0.5]", "[9.5, 5.5]"),
                4.0 + 5.0 * kSqrt2);
  // Round the L-shaped wall (y = 4 top): from (2, 2) up to (2, 4), along to (4, 4) (the wall's top
  // corner forbids the diagonal from (2, 3)), then one diagonal to (5, 3): 4 + sqrt(2).
  expect_octile(map_problem("ell", {".......", "...@...", "...@...", ".@@@...", "......."}, "{type: point}",
                            "[2.5, 2.5]", "[5.5, 3.5]"),
                4.0 + kSqrt2);
  // A wall with its only gap at the bottom row, from the top left to the top right.
  const world::Problem gap = map_problem("gap", {"...@...", "...@...", "...@...", "...@...", "......."}, "{type: point}",
                                         "[0.5, 4.5]", "[6.5, 4.5]");
  // Down the left side: (0,4) (1,3) (2,2) diagonals [2 sqrt 2], (2,1) (2,0) straight [2], (3,0)
  // (4,0) straight [2], then (4,1) (4,2) straight [2], (5,3) (6,4) diagonals [2 sqrt 2]: 6 + 4 sqrt 2.
  // (The diagonal (2,1)->(3,0) would cut (3,1), blocked.)
  expect_octile(gap, 6.0 + 4.0 * kSqrt2);
}

TEST(GridDp, SameResultForEverySeedAndThroughTheRegistry) {
  const world::Problem p = map_problem("seeds", {"..........", "..@@@@@...", "......@...", "...@..@...", ".........."},
                                       "{type: point}", "[0.5, 0.5]", "[9.5, 4.5]");
  const PlanResult a = run(p, {}, 1), b = run(p, {}, 99);
  ASSERT_EQ(a.status, core::PlanStatus::kSolved);
  ASSERT_EQ(a.path.size(), b.path.size());
  for (std::size_t i = 0; i < a.path.size(); ++i) EXPECT_EQ(a.path[i], b.path[i]);
  EXPECT_TRUE(builtin_planners().contains("grid-dp"));
}

TEST(GridDp, UnreachableGoalIsUnsolvable) {
  // The goal's cell touches the rest only at corners.
  const world::Problem p = map_problem("pocket", {".@...", "@.@..", ".@..."}, "{type: point}", "[4.5, 0.5]", "[1.5, 1.5]");
  const PlanResult r = run(p);
  EXPECT_EQ(r.status, core::PlanStatus::kUnsolvable);
  EXPECT_TRUE(r.path.empty());
}

TEST(GridDp, PointRobotIsFreeOnlyInsideFreeCells) {
  const world::Problem p = map_problem("cells", {"..", "@."}, "{type: point}", "[0.5, 1.5]", "[1.5, 0.5]");
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  auto at = [](double x, double y) {
    State s(2);
    s << x, y;
    return s;
  };
  EXPECT_TRUE(checker->is_valid(at(1.5, 0.5)));
  EXPECT_FALSE(checker->is_valid(at(0.5, 0.5)));   // in the blocked cell
  EXPECT_FALSE(checker->is_valid(at(1.0, 0.25)));  // on its edge
  EXPECT_FALSE(checker->is_valid(at(2.5, 0.5)));   // outside the map
  // (0, 1) -> (1, 0) would cut the blocked corner: round by (1, 1), 2 steps.
  expect_octile(p, 2.0);
}

TEST(GridDp, DiscOnTheRoomsMapKeepsAwayWithInflation) {
  const world::Problem p = world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems/movingai-rooms.yaml");
  const PlanResult plain = run(p);
  ASSERT_EQ(plain.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, plain.path, 2);
  GridDpSettings wide;
  wide.inflation_radius = 1.0;
  wide.cost_scaling_factor = 2.0;
  const PlanResult kept = run(p, wide);
  ASSERT_EQ(kept.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, kept.path, 2);
  EXPECT_GE(length(p, kept.path), length(p, plain.path) - 1e-9);
  // Mean clearance along the path's states grows when cells near walls cost more.
  auto mean_clearance = [&](const std::vector<State>& path) {
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    double sum = 0.0;
    for (const State& s : path) sum += checker->clearance(s).distance;
    return sum / static_cast<double>(path.size());
  };
  EXPECT_GT(mean_clearance(kept.path), mean_clearance(plain.path));
}

// grid-dp takes its map from Environment::as_map(): present on map worlds only.
TEST(GridDp, OnlyMapWorldsOfferTheMap) {
  const world::Problem map = map_problem("offered", {"..", ".."}, "{type: point}", "[0.5, 0.5]", "[1.5, 1.5]");
  ASSERT_NE(map.environment->as_map(), nullptr);
  EXPECT_EQ(&map.environment->as_map()->grid(), map.environment->obstacles_2d().grid.get());
  for (const char* file : {"problems/walls.yaml", "problems/walls3d.yaml"}) {
    EXPECT_EQ(world::load_problem(fs::path(AMP_SOURCE_DIR) / file).environment->as_map(), nullptr) << file;
  }
}

void expect_refused(const world::Problem& p) {
  try {
    run(p);
    FAIL() << p.name << " was planned";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "grid-dp plans for a point or disc robot on a map world (map_server or MovingAI)");
  }
}

TEST(GridDp, RefusesWorldsThatAreNotMapsAndBadSettings) {
  expect_refused(world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems/walls.yaml"));
  expect_refused(map_problem("rigid", {"....", "...."}, "{type: rigid2d, shapes: [{circle: {center: [0, 0], radius: 0.2}}]}",
                             "[0.5, 0.5, 0]", "[3.5, 1.5, 0]"));
  GridDpSettings bad;
  bad.penalty = -1.0;
  EXPECT_THROW(GridDp{bad}, ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
