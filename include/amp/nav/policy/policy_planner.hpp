#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/nav/policy/policy_search.hpp"
#include "amp/nav/policy/policy_value.hpp"
#include "amp/world/inflation_cost.hpp"

namespace amp::nav {

class GridNavWorld;

struct PolicyPlannerSettings {
  // The value function's obstacle cost (Nav2's inflation layer) beyond the footprint's radius.
  double inflation = 0.5;             // m
  double cost_scaling_factor = 10.0;  // 1/m
  double penalty = 2.0;               // extra cost per length at the footprint
  PolicyRewardSettings reward{};
  PolicySearchSettings search{};
};

// Every phase of the paper's Figure 3.
struct PolicyPlan {
  std::vector<Eigen::Vector2d> dp_path;  // (a) the value function's maximum-likelihood cells' centres
  PolicySearchResult search;             // (b) projected, (c) searched, (d) with insertions
  int squared_crossings = 0;             // narrow passages then crossed square-on (in `search.final`)
  // `stop` fired: during value iteration (no waypoints at all), or during the search (`search.final`
  // is the last policy it kept).
  bool stopped = false;
};

// Table 1 of "Policy search seeded by a value function" on a map: value iteration from the goal
// over the map's cells (world::GridCostToGo; a cell is free when the footprint's disc fits at its
// centre, and costs more near obstacles), the maximum-likelihood path from the start, its projection
// to 5-D waypoints at the top speed (project_to_waypoints), then search_policy. Throws
// ParameterError with one line for a start or goal where the disc is not free, a goal the footprint
// cannot reach ("no passage wide enough for the footprint" when a point could), or bad settings.
// `stop` (optional) ends value iteration and the search early (PolicyPlan::stopped).
PolicyPlan plan_policy(const GridNavWorld& world, const Eigen::Vector2d& start, const Eigen::Vector2d& goal, double radius,
                       const PolicyPlannerSettings& settings = {}, const core::StopCondition* stop = nullptr);
// The same for any footprint, checked at the headings of the path: value iteration runs for one of
// its discs, and a projected policy whose segments or turns in place the whole footprint cannot
// drive is refused ("no passage wide enough for the footprint ... at its heading"), as is a start
// where it cannot turn from facing the goal (where the robot starts) onto the path. The final
// policy then crosses narrow passages square-on (square_crossings; `value_final` is its value).
PolicyPlan plan_policy(const GridNavWorld& world, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                       const Footprint& footprint, const PolicyPlannerSettings& settings = {},
                       const core::StopCondition* stop = nullptr);

}  // namespace amp::nav
