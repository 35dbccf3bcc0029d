#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/core/state.hpp"

namespace amp::nav {

// Where a grid path lies: cells of side cell_size, row-major `width` wide, cell (0, 0) with its outer
// corner at origin (world::GridCells, FreeMask and OccupancyGrid all index this way).
struct GridFrame {
  int width = 0;
  double cell_size = 1.0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d center(int cell) const {
    return origin + cell_size * Eigen::Vector2d(cell % width + 0.5, cell / width + 0.5);
  }
};

// The initial policy of policy search (Sec. 3.3 and Figure 1 of "Policy search seeded by a value
// function"): the value function's maximum-likelihood cell path projected to 5-D waypoints
// (x, y, theta, v, omega; core::UnicycleSpace's layout). Each cell's action is its step to the next
// cell; neighbours sharing one action merge into a segment, and the segments' endpoints are the
// waypoints. The first and last are the start and the goal themselves (not their cells' centres).
// Headings: each waypoint faces along the segment it begins (the last along the one it ends); speed
// `cruise` and turn rate 0, which the search then changes. A path of one cell gives the start and
// the goal. Empty cells give an empty result.
std::vector<State> project_to_waypoints(const std::vector<int>& cells, const GridFrame& frame,
                                        const Eigen::Vector2d& start, const Eigen::Vector2d& goal, double cruise);

}  // namespace amp::nav
