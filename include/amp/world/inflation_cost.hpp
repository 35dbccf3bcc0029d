#pragma once
#include "amp/world/grid_cost_to_go.hpp"

namespace amp::world {

class GridObstacles;

// Obstacle costs of a map's cells for a robot's centre, after Nav2's inflation layer: a cell whose
// centre is closer than the inscribed radius to a blocked square (or the map's edge) is lethal, i.e.
// not free; within the inflation radius it costs penalty * exp(-k (d - inscribed)), d the exact
// distance from its centre to the nearest blocked square, k the cost scaling factor; beyond, 0.
// Nav2's layer scales the same curve to 252 and its Smac planners charge length * (1 + cost_penalty
// * cost / 252), which is length * (1 + penalty * exp(...)) here (GridCells::cost).
struct InflationSettings {
  double inscribed_radius = 0.0;     // m; 0: a point robot, a cell is free iff it is not blocked
  double inflation_radius = 0.0;     // m, the safety range; <= inscribed: no costs
  double cost_scaling_factor = 10.0; // 1/m (Nav2's default)
  double penalty = 2.0;              // cost at the inscribed radius (Nav2 Smac's cost_penalty)
  // Throws ParameterError naming the setting for a negative or non-finite value.
  void validate() const;
};

// The map's cells as a search grid under `s` (GridCells::cost empty when there is no inflation).
GridCells inflate(const GridObstacles& obstacles, const InflationSettings& s);

}  // namespace amp::world
