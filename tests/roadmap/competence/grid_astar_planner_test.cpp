#include "amp/roadmap/competence/grid_astar_planner.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/se3_space.hpp"
#include "support/path_checks.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kStep = 10.0 / 128.0;  // the point world's grid step at 128 steps per axis

struct Bench {
  world::Problem problem;
  core::Counters counters;
  std::unique_ptr<world::ValidityChecker> checker;
  std::unique_ptr<GridAStarPlanner> astar;
  explicit Bench(world::Problem p, GridAStarSettings s = {}) : problem(std::move(p)) {
    checker = problem.environment->make_checker(counters);
    astar = std::make_unique<GridAStarPlanner>(*problem.space, *checker, s);
  }
};

world::Problem free_plane() {
  world::Problem p = test::point_problem(true);
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kPoint);
  return p;
}

// Consecutive states of a grid path differ by one step along one axis (the last hop, onto b, by
// at most half a step per axis).
void expect_grid_moves(const std::vector<State>& path) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const State d = path[i] - path[i - 1];
    int moved = 0;
    for (int j = 0; j < d.size(); ++j) {
      if (std::abs(d[j]) > 1e-9) {
        ++moved;
        EXPECT_NEAR(std::abs(d[j]), kStep, 1e-9) << "state " << i;
      }
    }
    EXPECT_EQ(moved, 1) << "state " << i;
  }
}

TEST(GridAStar, FreeSpaceGoesStraightWithCompetenceOne) {
  Bench s(free_plane());
  const State a = test::state2(1, 1), b = test::state2(8, 3);
  s.astar->set_threshold(1.0);  // a straight free path has O = 1 throughout
  ASSERT_TRUE(s.astar->connect(a, b));
  const GridSearchStats st = s.astar->last();
  // b is 89.6 and 25.6 steps away: its cell is (90, 26), 116 moves, 117 cells.
  EXPECT_EQ(st.path_cells, 117u);
  EXPECT_DOUBLE_EQ(st.competence, 1.0);
  EXPECT_FALSE(st.abandoned);
  EXPECT_EQ(s.counters.cd_calls(), st.cells_checked + st.move_checks);  // every check is counted, once
  EXPECT_EQ(st.move_checks, 0u);  // a step (0.078) is shorter than the space's resolution (0.14)
  EXPECT_EQ(s.counters.lp_calls(), 1u);
  EXPECT_EQ(s.counters.lp_successes(), 1u);

  std::vector<State> way;
  s.astar->edge_waypoints(a, b, way);
  ASSERT_EQ(way.size(), 116u);  // every cell but a's; b's cell is not b
  std::vector<State> path{a};
  path.insert(path.end(), way.begin(), way.end());
  expect_grid_moves(path);
  EXPECT_NEAR(way.back()[0], 1 + 90 * kStep, 1e-12);
  EXPECT_NEAR(way.back()[1], 1 + 26 * kStep, 1e-12);
  EXPECT_LE((way.back() - b).cwiseAbs().maxCoeff(), kStep / 2);
}

TEST(GridAStar, CellsAreCheckedOnlyWhenFirstReached) {
  world::Problem p = test::point_problem(true);
  std::vector<State> checked;
  auto env = std::make_shared<test::BoxEnvironment>(
      std::vector<test::Box>{{4.5, 0.0, 5.5, 4.6}, {4.5, 5.4, 5.5, 10.0}}, test::RobotKind::kPoint);
  env->set_record(&checked);
  p.environment = env;
  Bench s(p);
  ASSERT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  ASSERT_EQ(checked.size(), s.astar->last().cells_checked);
  std::vector<std::pair<long, long>> cells;
  for (const State& c : checked) cells.emplace_back(std::lround(c[0] / kStep * 64), std::lround(c[1] / kStep * 64));
  std::sort(cells.begin(), cells.end());
  EXPECT_EQ(std::adjacent_find(cells.begin(), cells.end()), cells.end()) << "a cell was checked twice";
}

TEST(GridAStar, DetourThroughTheGapNeedsCompetence) {
  const world::Problem p = test::point_problem(true);  // (1,2) -> (9,2), the gap at y in [4.6, 5.4]
  Bench s(p);
  s.astar->set_threshold(1.0);
  EXPECT_FALSE(s.astar->connect(p.seeds[0], p.seeds[1]));
  EXPECT_TRUE(s.astar->last().abandoned);

  s.astar->set_threshold(kInf);
  ASSERT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  const GridSearchStats unlimited = s.astar->last();
  EXPECT_GT(unlimited.competence, 1.0);
  // The largest O seen is exactly the threshold that just suffices.
  s.astar->set_threshold(unlimited.competence);
  EXPECT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  s.astar->set_threshold(unlimited.competence * 0.999);
  EXPECT_FALSE(s.astar->connect(p.seeds[0], p.seeds[1]));

  std::vector<State> way;
  s.astar->edge_waypoints(p.seeds[0], p.seeds[1], way);
  std::vector<State> path{p.seeds[0]};
  path.insert(path.end(), way.begin(), way.end());
  path.push_back(p.seeds[1]);
  expect_grid_moves({path.begin(), path.end() - 1});
  double highest = 0;
  for (const State& q : path) highest = std::max(highest, q[1]);
  EXPECT_GT(highest, 4.6);  // it went up to the gap
  core::Counters c2;
  const auto checker = p.environment->make_checker(c2);
  for (const State& q : path) EXPECT_TRUE(checker->is_valid(q));
}

TEST(GridAStar, AMoveThatClipsAThinObstacleIsForbiddenAndSearchedAround) {
  // A sliver x in [4.52, 4.54] between the grid columns 4.5156 and 4.5938 of a search from (1, 1):
  // every cell is free, but the straight row y = 1 crosses it. Edges are checked at 0.01.
  world::Problem p = free_plane();
  auto space = std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
  space->set_resolution(0.01);
  p.space = space;
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{{4.52, 0.9, 4.54, 1.1}},
                                                          test::RobotKind::kPoint);
  Bench s(p);
  const State a = test::state2(1, 1), b = test::state2(8, 1);
  ASSERT_TRUE(s.astar->connect(a, b));
  const GridSearchStats st = s.astar->last();
  EXPECT_GE(st.repairs, 3u);  // rows y = 0.92, 1.0, 1.08 all cross the sliver
  EXPECT_GT(st.move_checks, 0u);
  EXPECT_EQ(s.counters.cd_calls(), st.cells_checked + st.move_checks);
  std::vector<State> way;
  s.astar->edge_waypoints(a, b, way);
  std::vector<State> path{a};
  path.insert(path.end(), way.begin(), way.end());
  path.push_back(b);
  p.seeds = {a, b};
  amp::test::expect_valid_path(p, path, 4);
}

TEST(GridAStar, ClosedWallIsExhaustedNotAbandoned) {
  const world::Problem p = test::point_problem(false);
  Bench s(p);
  EXPECT_FALSE(s.astar->connect(p.seeds[0], p.seeds[1]));
  EXPECT_FALSE(s.astar->last().abandoned);
  // The left front fills the free cells left of the wall (about 57 x 129) before it gives up.
  EXPECT_GT(s.astar->last().cells_checked, 5000u);
  EXPECT_EQ(s.counters.lp_successes(), 0u);
}

TEST(GridAStar, MaxCellsStopsTheSearch) {
  const world::Problem p = test::point_problem(false);
  GridAStarSettings g;
  g.max_cells = 500;
  Bench s(p, g);
  EXPECT_FALSE(s.astar->connect(p.seeds[0], p.seeds[1]));
  EXPECT_TRUE(s.astar->last().abandoned);
  EXPECT_TRUE(s.astar->last().capped);
  EXPECT_EQ(s.astar->last().cells_checked, 500u);
}

TEST(GridAStar, BlockedTargetCellFails) {
  const world::Problem p = test::point_problem(true);
  Bench s(p);
  // b = (4.49, 2) is free, but the cell nearest it (44.67 -> 45 steps from a.x = 1, at x = 4.516)
  // lies in the wall: the search ends after that one check.
  const State a = test::state2(1, 2), b = test::state2(4.49, 2);
  ASSERT_LT(4.49, 4.5);
  EXPECT_FALSE(s.astar->connect(a, b));
  EXPECT_EQ(s.astar->last().cells_checked, 1u);
}

TEST(GridAStar, SameInputsSameSearch) {
  const world::Problem p = test::point_problem(true);
  Bench s(p);
  ASSERT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  const GridSearchStats first = s.astar->last();
  std::vector<State> w1, w2;
  s.astar->edge_waypoints(p.seeds[0], p.seeds[1], w1);
  s.astar->connect(test::state2(2, 8), test::state2(3, 1));  // something else in between
  ASSERT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  EXPECT_EQ(s.astar->last().cells_checked, first.cells_checked);
  EXPECT_EQ(s.astar->last().expanded, first.expanded);
  s.astar->edge_waypoints(p.seeds[0], p.seeds[1], w2);
  ASSERT_EQ(w1.size(), w2.size());
  for (std::size_t i = 0; i < w1.size(); ++i) EXPECT_EQ(w1[i], w2[i]);
  // Replaying the accepted search's moves gives the same states without a CD call.
  ASSERT_TRUE(s.astar->connect(p.seeds[0], p.seeds[1]));
  std::vector<std::uint8_t> moves;
  s.astar->last_moves(moves);
  EXPECT_EQ(moves.size(), first.path_cells - 1);
  const std::uint64_t calls = s.counters.cd_calls();
  std::vector<State> w3;
  s.astar->replay(p.seeds[0], p.seeds[1], moves, w3);
  EXPECT_EQ(s.counters.cd_calls(), calls);
  EXPECT_EQ(w3, w1);
}

TEST(GridAStar, ContinuousJointGoesTheShortWayRound) {
  world::Problem p = test::arm_problem();
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{}, test::RobotKind::kArm);
  Bench s(p);
  const State a = test::state2(3.0, 0.0), b = test::state2(-3.0, 0.0);
  ASSERT_TRUE(s.astar->connect(a, b));
  // 2 pi - 6 = 0.2832 rad is 5.77 steps of 2 pi / 128: 6 steps (7 cells), not 122.
  EXPECT_EQ(s.astar->last().path_cells, 7u);
}

TEST(GridAStar, Se3ChartRoundTripsAndSearches) {
  const auto space = std::make_shared<core::Se3Space>(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10), 1.0);
  GridChart chart(*space, 128);
  const State origin = core::Se3Space::make_state(Eigen::Vector3d(5, 5, 5),
                                                   Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())));
  chart.set_origin(origin);
  const double x[6] = {1.0, -2.0, 0.5, 0.3, -0.4, 1.1};
  State s;
  ASSERT_TRUE(chart.state_at(x, s));
  double back[6];
  chart.coordinates(s, back);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], x[i], 1e-9);
  const double outside[6] = {6.0, 0, 0, 0, 0, 0};  // x = 11 > 10
  EXPECT_FALSE(chart.state_at(outside, s));

  // A free space: a quarter turn about z and a shift, found on the grid and ending next to b.
  class Free final : public world::ValidityChecker {
   public:
    using ValidityChecker::ValidityChecker;
   private:
    bool check(const State&) const override { return true; }
    world::Clearance compute_clearance(const State&) const override { return {}; }
    double compute_free_radius(const State&) const override { return 1e9; }
    double compute_motion_bound(const State&, const State&) const override { return 1.0; }
  };
  core::Counters counters;
  Free free(counters);
  GridAStarPlanner astar(*space, free);
  const State b = core::Se3Space::make_state(Eigen::Vector3d(6, 5, 5),
                                              Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ())));
  ASSERT_TRUE(astar.connect(origin, b));
  std::vector<State> way;
  astar.edge_waypoints(origin, b, way);
  ASSERT_FALSE(way.empty());
  EXPECT_LT(space->distance(way.back(), b), 0.1);
  EXPECT_DOUBLE_EQ(astar.last().competence, 1.0);
}

TEST(GridAStar, RejectsBadSettings) {
  const world::Problem p = test::point_problem(true);
  core::Counters c;
  const auto checker = p.environment->make_checker(c);
  GridAStarSettings g;
  g.steps = 0;
  EXPECT_THROW(GridAStarPlanner(*p.space, *checker, g), ParameterError);
  g.steps = 128;
  g.h_weight = 0;
  EXPECT_THROW(GridAStarPlanner(*p.space, *checker, g), ParameterError);
  GridAStarPlanner ok(*p.space, *checker);
  EXPECT_THROW(ok.set_threshold(0.0), ParameterError);
  EXPECT_THROW(ok.set_threshold(-1.0), ParameterError);
  EXPECT_THROW(ok.set_threshold(std::nan("")), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
