#include "amp/nav/policy/policy_planner.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/policy/footprint_drive.hpp"
#include "amp/nav/policy/waypoint_projection.hpp"
#include "amp/world/grid_cost_to_go.hpp"

namespace amp::nav {

namespace {

std::string point_text(const Eigen::Vector2d& p) { return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")"; }

std::string footprint_text(const Footprint& f) {
  if (f.is_disc()) return "radius " + std::to_string(f.disc_radius());
  return std::to_string(f.length()) + " m x " + std::to_string(f.width()) + " m";
}

}  // namespace

PolicyPlan plan_policy(const GridNavWorld& world, const Eigen::Vector2d& start, const Eigen::Vector2d& goal, double radius,
                       const PolicyPlannerSettings& settings, const core::StopCondition* stop) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw ParameterError("the footprint's radius must be > 0, got " + std::to_string(radius));
  }
  return plan_policy(world, start, goal, Footprint::disc(radius), settings, stop);
}

PolicyPlan plan_policy(const GridNavWorld& world, const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                       const Footprint& footprint, const PolicyPlannerSettings& settings,
                       const core::StopCondition* stop) {
  // Value iteration and the grid path treat the footprint as one of its discs, which any pose of it
  // needs room for; the waypoints are then checked with the whole footprint at their headings.
  const double radius = footprint.disc_radius();
  if (!world.disc_free(start, radius)) throw ParameterError("start " + point_text(start) + ": the robot's footprint is not free there");
  if (!world.disc_free(goal, radius)) throw ParameterError("goal " + point_text(goal) + ": the robot's footprint is not free there");
  const PolicyValue value(world, footprint, settings.reward);
  world::InflationSettings inflation;
  inflation.inscribed_radius = radius;
  inflation.inflation_radius = radius + settings.inflation;
  inflation.cost_scaling_factor = settings.cost_scaling_factor;
  inflation.penalty = settings.penalty;
  world::GridCostToGo dp(world::inflate(world.obstacles(), inflation));
  const world::OccupancyGrid& grid = world.grid();
  // The cell of a point, or a free neighbour the disc reaches straight (its own may be too near a wall).
  auto cell_of = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2i c = grid.world_to_cell(p);
    int best = -1;
    double best_d = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (!dp.free(c.x() + dx, c.y() + dy)) continue;
        const Eigen::Vector2d q = grid.cell_center(c.x() + dx, c.y() + dy);
        const double d = (q - p).norm();
        if ((best < 0 || d < best_d) && segment_free(world, p, q, radius)) best = dp.index(c.x() + dx, c.y() + dy), best_d = d;
      }
    }
    return best;
  };
  const int from = cell_of(start), to = cell_of(goal);
  const auto stopped = [stop] { return stop != nullptr && stop->time_up(); };
  PolicyPlan plan;
  if (from >= 0 && to >= 0 && !dp.compute(to, stopped)) {
    plan.stopped = true;  // value iteration cut short: no path to project
    return plan;
  }
  if (from < 0 || to < 0 || dp.distance(from) == world::GridCostToGo::kUnreachable) {
    world::GridCostToGo point(world::inflate(world.obstacles(), {}));
    const Eigen::Vector2i a = grid.world_to_cell(start), b = grid.world_to_cell(goal);
    if (!point.compute(point.index(b.x(), b.y()), stopped)) {
      plan.stopped = true;  // which refusal applies is not known yet
      return plan;
    }
    if (point.distance(point.index(a.x(), a.y())) < world::GridCostToGo::kUnreachable) {
      throw ParameterError("no passage wide enough for the footprint (" + footprint_text(footprint) +
                           ") joins the start and the goal");
    }
    throw ParameterError("the goal " + point_text(goal) + " is not reachable from the start " + point_text(start));
  }
  const std::vector<int> cells = dp.path(from);
  for (int c : cells) plan.dp_path.push_back(grid.cell_center(c % grid.width(), c / grid.width()));
  const GridFrame frame{grid.width(), grid.resolution(), grid.origin()};
  std::vector<State> projected = project_to_waypoints(cells, frame, start, goal, settings.search.v_max);
  if (!footprint.is_disc() && !policy_free(value, projected) && !make_drivable(value, projected, grid.resolution())) {
    if (!turn_drivable(value, projected, 0)) {
      throw ParameterError("start " + point_text(start) + ": the footprint (" + footprint_text(footprint) +
                           ") cannot turn there from facing the goal onto the path");
    }
    throw ParameterError("no passage wide enough for the footprint (" + footprint_text(footprint) +
                         ") at its heading: the grid path's turns or segments hit an obstacle");
  }
  plan.search = search_policy(std::move(projected), value, settings.search, stop);
  plan.stopped = plan.search.stopped;
  if (!footprint.is_disc()) {
    plan.squared_crossings = square_crossings(value, plan.search.final, grid.resolution());
    if (plan.squared_crossings > 0) plan.search.value_final = value.total(plan.search.final);
  }
  return plan;
}

}  // namespace amp::nav
