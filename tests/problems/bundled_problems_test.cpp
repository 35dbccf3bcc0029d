// Every bundled problem loads, and PRM and UAS (which must take OMPL.app .cfg problems unchanged) each solve it within the problem's limits with a path that starts
// at the start, ends at the goal and re-checks collision-free, with a fresh checker, at the space's
// resolution (edges are checked at discrete states, as in OMPL: a corner thinner than the resolution
// can be clipped between two of them, so a finer re-check is not a property PRM promises); the same
// seed gives the same path and the same CD count.
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"
#include "support/sanitizer_build.hpp"

#include "amp/core/counters.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp {
namespace {

std::filesystem::path problem_file(const std::string& name) {
  return std::filesystem::path(AMP_SOURCE_DIR) / "problems" / name;
}


using Case = std::tuple<std::string, std::string>;  // problem file, planner

// Every problem × planner pair; under the sanitizers, without the twelve pairs that take 15-70 s
// there (their planners run on the other problems, and their problems under other planners): the
// Release suite runs them all, and the sanitizers look for memory errors and undefined behaviour,
// which the planners' code reaches on the smaller problems as well.
std::vector<Case> cases(const std::vector<std::string>& files, const std::vector<std::string>& planners) {
  const std::set<Case> heavy = {
      {"scara-wicket.yaml", "prm"},   {"scara-wicket.yaml", "uas"},   {"scara-wicket.yaml", "prm-c"},
      {"scara-wicket.yaml", "prm-g"}, {"scara-wicket.yaml", "prm-l"}, {"puzzle.yaml", "prm"},
      {"puzzle.yaml", "prm-c"},       {"puzzle.yaml", "prm-g"},       {"hook.yaml", "prm"},
      {"hook.yaml", "uas"},           {"walls3d.yaml", "prm"},        {"walls3d.yaml", "uas"}};
  std::vector<Case> out;
  for (const auto& f : files)
    for (const auto& pl : planners)
      if (!amp::test::kSanitizerBuild || !heavy.contains({f, pl})) out.emplace_back(f, pl);
  return out;
}

class BundledProblem : public ::testing::TestWithParam<Case> {};

// "maze_rrt_connect": the file's stem and the planner, as a test name.
std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string n = std::filesystem::path(std::get<0>(info.param)).stem().string() + "_" + std::get<1>(info.param);
  for (char& c : n) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return n;
}

TEST_P(BundledProblem, SolvedWithAValidReproduciblePath) {
  const auto& [file, planner] = GetParam();
  const world::Problem p = world::load_problem(problem_file(file));
  const auto a = roadmap::execute_run(p, planner, {}, 1, p.defaults.time_limit_s, p.defaults.node_limit);
  ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << p.name << ": " << a.record.message;
  amp::test::expect_valid_path(p, a.path);
  EXPECT_GT(a.record.cd_calls(), 0u);
  EXPECT_GT(a.record.path_length, 0.0);

  const auto b = roadmap::execute_run(p, planner, {}, 1, p.defaults.time_limit_s, p.defaults.node_limit);
  ASSERT_EQ(b.path.size(), a.path.size());
  for (std::size_t i = 0; i < a.path.size(); ++i) EXPECT_EQ(a.path[i], b.path[i]);
  EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls());
  EXPECT_EQ(a.record.nodes, b.record.nodes);
}

INSTANTIATE_TEST_SUITE_P(Problems, BundledProblem,
                         ::testing::ValuesIn(cases({"maze.yaml", "l-tunnel.yaml", "hook.yaml", "walls.yaml",
                                                    "linkage.yaml", "maze3d.yaml", "walls3d.yaml", "office-map.yaml",
                                                    "movingai-rooms.yaml", "ompl/gap_planar.cfg",
                                                    "ompl/cage_window.cfg", "scara-wicket.yaml", "puzzle.yaml"},
                                                   {"prm", "uas"})),
                         case_name);

// RRT-Connect, the bidirectional tree planner, on a problem of each kind: planar, polygon robot,
// arm, 3-D, SCARA.
INSTANTIATE_TEST_SUITE_P(RrtConnect, BundledProblem,
                         ::testing::ValuesIn(cases({"maze.yaml", "hook.yaml", "linkage.yaml", "walls3d.yaml",
                                                    "scara-wicket.yaml"},
                                                   {"rrt-connect"})),
                         case_name);

// Section 3's planners on its problems (the A* grid local planner's paths are checked at the
// space's resolution too, between grid states), and on an arm and an OMPL.app SE3 problem.
INSTANTIATE_TEST_SUITE_P(CompetencePrms, BundledProblem,
                         ::testing::ValuesIn(cases({"scara-wicket.yaml", "puzzle.yaml", "linkage.yaml",
                                                    "ompl/cage_window.cfg"},
                                                   {"prm-c", "prm-g", "prm-l"})),
                         case_name);

}  // namespace
}  // namespace amp
