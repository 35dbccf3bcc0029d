#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/free_mask.hpp"
#include "amp/world/grid_cost_to_go.hpp"

namespace amp::nav {

class NavWorld;

// The free space of a disc robot rasterised (the world inflated by the radius), as navigation
// methods are measured against it: which cells the robot can reach from a point, and the
// grid-shortest length between two points (8-connected, sqrt 2 diagonals, no corner cutting),
// the reference for path quality. One Dijkstra per goal; buffers are reused.
class ReferenceGrid {
 public:
  // cell_size <= 0 chooses the longer side of the world's bounds / 256. Throws ParameterError as
  // rasterize_free_space does.
  ReferenceGrid(const NavWorld& world, double radius, double cell_size = 0.0);

  const FreeMask& mask() const { return mask_; }
  // The free cell holding p, or the free one of its 8 neighbours nearest to p; -1 when none is free
  // (p outside, or in a gap narrower than a cell).
  int cell_near(const Eigen::Vector2d& p) const;
  // 1 for every cell reachable from p's cell (cell_near), 0 elsewhere; all 0 when p has no cell.
  std::vector<std::uint8_t> reachable_from(const Eigen::Vector2d& p);
  // Grid-shortest length from a to b: the octile path between their cells plus each point's
  // distance to its cell's centre; +infinity when they are not connected or have no cell.
  double shortest_length(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

 private:
  FreeMask mask_;
  world::GridCostToGo paths_;
};

}  // namespace amp::nav
