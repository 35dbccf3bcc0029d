#pragma once
#include <memory>

#include "amp/nav/nav_world.hpp"
#include "amp/world/grid_environment.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::nav {

// A navigation world on an occupancy map (ROS map_server or MovingAI): blocked cells (occupied or
// unknown) are closed squares, and so is everything outside the map. Discs and nearest points come
// from world::GridObstacles (distance transform + exact row scans); rays walk the cells exactly
// (Amanatides and Woo 1987) and stop where they first touch a blocked square or the map's border,
// so a ray along a wall's face or through the corner between two diagonal blocked cells stops.
class GridNavWorld final : public NavWorld {
 public:
  // Throws ParameterError for a null grid.
  explicit GridNavWorld(std::shared_ptr<const world::OccupancyGrid> grid);

  const world::OccupancyGrid& grid() const { return obstacles_.grid(); }
  const world::GridObstacles& obstacles() const { return obstacles_; }

  const Eigen::AlignedBox2d& bounds() const override { return extent_; }
  bool disc_free(const Eigen::Vector2d& p, double r) const override { return obstacles_.disc_free(p, r); }
  NearestObstacle nearest_obstacle(const Eigen::Vector2d& p) const override;
  double distance_up_to(const Eigen::Vector2d& p, double limit) const override {
    return obstacles_.point_distance_up_to(p, limit);
  }
  double ray_cast(const Eigen::Vector2d& p, const Eigen::Vector2d& dir, double max_range) const override;
  // Sets cells (and the cells under shapes) occupied or free on a copy of the map.
  std::shared_ptr<const NavWorld> changed(const ObstacleChange& change) const override;
  const GridNavWorld* as_map() const override { return this; }

 private:
  // A cell outside the map counts as blocked.
  bool blocked_or_outside(int cx, int cy) const;
  // The closed square of some blocked cell (or the outside) holds grid point g.
  bool touches_blocked(const Eigen::Vector2d& g) const;

  world::GridObstacles obstacles_;
  Eigen::AlignedBox2d extent_;
};

}  // namespace amp::nav
