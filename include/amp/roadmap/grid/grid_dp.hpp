#pragma once
#include "amp/core/settings_schema.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

// Obstacle costs of grid-dp: Nav2's inflation layer (world::InflationSettings). Off by default, so
// that a path is the shortest octile path.
struct GridDpSettings {
  double inflation_radius = 0.0;      // m beyond the robot's radius within which cells cost more; 0: none
  double cost_scaling_factor = 10.0;  // 1/m, the decay of the cost (Nav2's default)
  double penalty = 2.0;               // extra cost per length at the robot's radius (Nav2 Smac's cost_penalty)
  static const core::SettingsSchema<GridDpSettings>& schema();
  void validate() const { schema().validate(*this); }
};

// The optimal grid path on a map world (map_server or MovingAI): value iteration on the map's own
// cells from the goal (world::GridCostToGo: 8-connected, sqrt(2) diagonals, no corner cutting),
// then the maximum-likelihood descent from the start. A point robot (`robot: {type: point}`)
// occupies the cell it is in, as MovingAI's benchmarks assume: the path's length between cell
// centres is the octile length their scenario files list. A disc of radius r may enter a cell when
// it fits at the cell's centre. A straight step between two such cells is then free (along it the
// distance to the map's squares is least at an end), and so is a diagonal one (the squares' corners
// beside it lie level with its ends, but for the corner its four free cells share at its middle);
// the path is certified regardless. With inflation_radius > 0 the steps cost more near
// obstacles (GridCells::cost) and the path keeps away from them.
//
// The path: the start, the centres of its cells, the goal; each segment is certified
// (EdgeCertifier) before the path is returned. With more than two seeds each leg is planned in
// turn. Deterministic (no random choice). PlanResult: `nodes` the cells the last leg's plan settled (the node
// limit stops the value iteration there: status node_limit),
// `edges` the path's steps; extra: cells, free_cells, reachable_cells, grid_cost.
class GridDp final : public Planner {
 public:
  explicit GridDp(GridDpSettings settings = {});
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  GridDpSettings settings_;
};

}  // namespace amp::roadmap
