#include "amp/roadmap/grid/grid_dp.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/world/grid_cost_to_go.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/inflation_cost.hpp"

namespace amp::roadmap {

const core::SettingsSchema<GridDpSettings>& GridDpSettings::schema() {
  using S = GridDpSettings;
  static const core::SettingsSchema<S> schema(
      "grid-dp",
      {core::real_field<S>("inflation_radius", &S::inflation_radius, 0, 1e9,
                           "m beyond the robot's radius within which cells cost more (0: the shortest path)"),
       core::real_field<S>("cost_scaling_factor", &S::cost_scaling_factor, 0, 1e9, "1/m, decay of the obstacle cost"),
       core::real_field<S>("penalty", &S::penalty, 0, world::GridCostToGo::kMaxCellCost,
                           "extra cost per length at the robot's radius")});
  return schema;
}

GridDp::GridDp(GridDpSettings settings) : settings_(settings) { settings_.validate(); }

namespace {

State point_state(const Eigen::Vector2d& p) {
  State s(2);
  s << p.x(), p.y();
  return s;
}

// The cell a seed enters the grid by: its own if free, else the free neighbour it reaches by a
// certified segment (a disc near a wall may not fit at its own cell's centre); -1 if none.
int entry_cell(const world::OccupancyGrid& grid, const world::GridCostToGo& dp, const State& seed,
               EdgeCertifier& certifier) {
  const Eigen::Vector2i c = grid.world_to_cell({seed[0], seed[1]});
  if (dp.free(c.x(), c.y())) return dp.index(c.x(), c.y());
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (!dp.free(c.x() + dx, c.y() + dy)) continue;
      const Eigen::Vector2d p = grid.cell_center(c.x() + dx, c.y() + dy);
      if (certifier.certify(seed, point_state(p))) return dp.index(c.x() + dx, c.y() + dy);
    }
  }
  return -1;
}

}  // namespace

PlanResult GridDp::plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng&) {
  const world::GridEnvironment* env = ctx.environment.as_map();
  if (env == nullptr || env->robot().kind == world::GridRobot::Kind::kRigid) {
    throw ParameterError("grid-dp plans for a point or disc robot on a map world (map_server or MovingAI)");
  }
  check_seeds(ctx);
  const world::OccupancyGrid& grid = env->grid();
  const double r = env->robot().kind == world::GridRobot::Kind::kDisc ? env->robot().radius : 0.0;
  world::InflationSettings inflation;
  inflation.inscribed_radius = r;
  if (settings_.inflation_radius > 0.0) inflation.inflation_radius = r + settings_.inflation_radius;
  inflation.cost_scaling_factor = settings_.cost_scaling_factor;
  inflation.penalty = settings_.penalty;
  world::GridCostToGo dp(world::inflate(env->obstacles(), inflation));
  EdgeCertifier certifier(ctx.space, ctx.checker, &stop);

  PlanResult result;
  result.status = core::PlanStatus::kSolved;
  double grid_cost = 0.0;
  std::size_t reachable = 0;
  result.path.push_back(ctx.seeds.front());
  for (std::size_t leg = 1; leg < ctx.seeds.size(); ++leg) {
    const State& from = ctx.seeds[leg - 1];
    const State& to = ctx.seeds[leg];
    const int goal = entry_cell(grid, dp, to, certifier);
    const int start = entry_cell(grid, dp, from, certifier);
    if (goal < 0 || start < 0) {
      result.status = core::PlanStatus::kUnsolvable;
      break;
    }
    // The settled cells are grid-dp's nodes, so the node limit bounds them exactly.
    const bool complete = dp.compute(goal, [&stop] { return stop.check(0) != core::StopReason::kNone; }, stop.node_limit());
    reachable = dp.settled();
    if (!complete) {
      result.status = dp.settled() == stop.node_limit() ? status_for(core::StopReason::kNodeLimit) : status_for(stop.check(0));
      break;
    }
    const std::vector<int> cells = dp.path(start);
    if (cells.empty()) {
      result.status = core::PlanStatus::kUnsolvable;
      break;
    }
    grid_cost += dp.distance(start);
    for (int cell : cells) {
      const Eigen::Vector2d p = grid.cell_center(cell % grid.width(), cell / grid.width());
      result.path.push_back(point_state(p));
    }
    result.path.push_back(to);
  }
  // Drop repeated states (a seed at its cell's centre), then certify every segment.
  std::vector<State> path;
  for (State& s : result.path) {
    if (path.empty() || ctx.space.distance(path.back(), s) > 0.0) path.push_back(std::move(s));
  }
  result.path.clear();
  if (result.status == core::PlanStatus::kSolved) {
    for (std::size_t i = 1; i < path.size() && result.status == core::PlanStatus::kSolved; ++i) {
      if (!certifier.certify(path[i - 1], path[i])) {
        const core::StopReason why = stop.check(0);
        result.status = why != core::StopReason::kNone ? status_for(why) : core::PlanStatus::kUnsolvable;
      }
    }
  }
  if (result.status == core::PlanStatus::kSolved) result.path = std::move(path);
  result.nodes = reachable;
  result.edges = result.path.empty() ? 0 : result.path.size() - 1;
  result.components = 1;
  const auto& cells = dp.cells();
  std::size_t free = 0;
  for (std::uint8_t f : cells.free) free += f != 0 ? 1 : 0;
  result.extra["cells"] = static_cast<double>(cells.free.size());
  result.extra["free_cells"] = static_cast<double>(free);
  result.extra["reachable_cells"] = static_cast<double>(reachable);
  result.extra["grid_cost"] = grid_cost;
  certifier.report(result.extra);
  return result;
}

}  // namespace amp::roadmap
