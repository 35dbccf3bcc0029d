// Policy search seeded by a value function (nav::plan_policy) on the bundled 20 m x 20 m office floor
// (problems/policy-office-floor.yaml, 400 x 400 cells), from its start to its goal, with the
// settings of `amp navigate --method policy-search`; and the value iteration part alone on the same
// map. Targets (issue 15): plan_policy <= 0.1 s on a 400 x 400 map (the paper: 7.0 +- 4.8 s).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "amp/nav/drive_settings.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/policy/policy_navigator.hpp"
#include "amp/nav/policy/policy_planner.hpp"
#include "amp/world/grid_cost_to_go.hpp"
#include "amp/world/inflation_cost.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace {

using namespace amp;

// The task as `amp navigate` builds it: the problem's nav task and its base world as a map.
const nav::NavTask& office_floor() {
  static const nav::NavTask task =
      nav::make_nav_task(world::load_problem(std::filesystem::path(AMP_SOURCE_DIR) / "problems/policy-office-floor.yaml"));
  return task;
}

// PolicyNavigator's planner settings with every parameter at its default.
nav::PolicyPlannerSettings navigator_settings() { return nav::PolicyNavigatorSettings{}.planner(nav::DriveSettings{}); }

// The grid plan_policy searches: the map's cells under the footprint's inflation costs.
world::GridCells inflated(const nav::GridNavWorld& world, double radius, const nav::PolicyPlannerSettings& s) {
  world::InflationSettings inflation;
  inflation.inscribed_radius = radius;
  inflation.inflation_radius = radius + s.inflation;
  inflation.cost_scaling_factor = s.cost_scaling_factor;
  inflation.penalty = s.penalty;
  return world::inflate(world.obstacles(), inflation);
}

void BM_PlanPolicyOfficeFloor(benchmark::State& state) {
  const nav::NavTask& task = office_floor();
  const nav::GridNavWorld& world = nav::map_world(task, "policy_planning_bench");
  const nav::PolicyPlannerSettings settings = navigator_settings();
  nav::PolicyPlan plan;
  for (auto _ : state) {
    plan = nav::plan_policy(world, task.start, task.goal, task.robot_radius, settings);
    benchmark::DoNotOptimize(plan.search.value_final);
  }
  // The result, to see at a glance that a speed-up leaves it unchanged.
  state.counters["dp_cells"] = static_cast<double>(plan.dp_path.size());
  state.counters["waypoints"] = static_cast<double>(plan.search.final.size());
  state.counters["sweeps"] = plan.search.sweeps;
  state.counters["insertions"] = plan.search.insertions;
  state.counters["value"] = plan.search.value_final;
}
BENCHMARK(BM_PlanPolicyOfficeFloor)->Unit(benchmark::kMillisecond);

// Value iteration from the goal's cell over the inflated grid (GridCostToGo::compute); with
// state.range(0) != 0 the inflation (world::inflate) is timed too, as plan_policy runs both.
void BM_ValueIterationOfficeFloor(benchmark::State& state) {
  const nav::NavTask& task = office_floor();
  const nav::GridNavWorld& world = nav::map_world(task, "policy_planning_bench");
  const nav::PolicyPlannerSettings settings = navigator_settings();
  const Eigen::Vector2i goal_cell = world.grid().world_to_cell(task.goal);
  world::GridCostToGo dp(inflated(world, task.robot_radius, settings));
  const int goal = dp.index(goal_cell.x(), goal_cell.y());
  if (!dp.free(goal_cell.x(), goal_cell.y())) {
    state.SkipWithError("the goal's cell is not free");
    return;
  }
  const bool with_inflation = state.range(0) != 0;
  for (auto _ : state) {
    if (with_inflation) dp = world::GridCostToGo(inflated(world, task.robot_radius, settings));
    dp.compute(goal);
    benchmark::DoNotOptimize(dp.distances().data());
  }
  long reached = 0;
  for (double d : dp.distances()) reached += d < world::GridCostToGo::kUnreachable ? 1 : 0;
  state.counters["reached"] = static_cast<double>(reached);
}
BENCHMARK(BM_ValueIterationOfficeFloor)->ArgName("with_inflation")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
