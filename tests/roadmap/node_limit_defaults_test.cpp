// A run's node limit (issue 34): the run's own, else the problem's, else the planner's default;
// roadmap planners default to 20000, grid-dp to none (its map bounds it).
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

const std::filesystem::path kProblems = std::filesystem::path(AMP_SOURCE_DIR) / "problems";

PlannerInfo planner_with_default(std::size_t nodes) {
  PlannerInfo info;
  info.name = "toy";
  info.default_node_limit = nodes;
  return info;
}

TEST(NodeLimitDefaults, RunBeatsProblemBeatsPlanner) {
  world::Problem p;
  const PlannerInfo planner = planner_with_default(700);
  EXPECT_EQ(resolve_node_limit(std::nullopt, p, planner), 700u);
  p.defaults.node_limit = 500;
  EXPECT_EQ(resolve_node_limit(std::nullopt, p, planner), 500u);
  EXPECT_EQ(resolve_node_limit(300, p, planner), 300u);
}

TEST(NodeLimitDefaults, GridDpHasNoneAndEveryOtherPlannerTheRoadmapDefault) {
  const PlannerRegistry& r = builtin_planners();
  for (const std::string& name : r.names()) {
    const std::size_t expected = name == "grid-dp" ? world::kNoNodeLimit : kDefaultNodeLimit;
    EXPECT_EQ(r.info(name).default_node_limit, expected) << name;
  }
  EXPECT_EQ(kDefaultNodeLimit, 20000u);
}

TEST(NodeLimitDefaults, ProblemFilesGiveOneOnlyWhenTheySayIt) {
  EXPECT_FALSE(world::load_problem(kProblems / "movingai-rooms.yaml").defaults.node_limit.has_value());
  EXPECT_EQ(world::load_problem(kProblems / "maze.yaml").defaults.node_limit, std::optional<std::size_t>(50000));
}

}  // namespace
}  // namespace amp::roadmap
