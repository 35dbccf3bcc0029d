#pragma once
#include <memory>
#include <vector>

#include "amp/nav/nav_world.hpp"
#include "amp/world/planar_world.hpp"

namespace amp::nav {

// A navigation world of polygons, circles and segment walls inside a bounding box, over
// world::PlanarWorld (shared with the planners' environment). Exact: rays meet the closed shapes
// (touching stops a ray); a disc is free when no obstacle comes nearer than its radius. Rays walk
// the PlanarWorld's broad-phase grid cell by cell (Amanatides and Woo 1987) and test only the edges
// and circles listed there; disc checks look only at the cells under the disc; nearest-obstacle
// queries skip every polygon whose bounding box is farther than the best distance so far.
class PolygonNavWorld final : public NavWorld {
 public:
  // Throws ParameterError for a null world.
  explicit PolygonNavWorld(std::shared_ptr<const world::PlanarWorld> world);
  // Builds the PlanarWorld; throws ParameterError for invalid shapes or bounds.
  PolygonNavWorld(world::Shapes2d obstacles, const Eigen::AlignedBox2d& bounds);

  const world::PlanarWorld& world() const { return *world_; }

  const Eigen::AlignedBox2d& bounds() const override { return world_->bounds(); }
  bool disc_free(const Eigen::Vector2d& p, double r) const override;
  NearestObstacle nearest_obstacle(const Eigen::Vector2d& p) const override;
  double ray_cast(const Eigen::Vector2d& p, const Eigen::Vector2d& dir, double max_range) const override;
  // Appear adds the shapes; vanish removes equal ones. Cells are refused (no map here).
  std::shared_ptr<const NavWorld> changed(const ObstacleChange& change) const override;
  const PolygonNavWorld* as_polygons() const override { return this; }

 private:
  // p lies in a closed obstacle polygon or circle.
  bool inside_obstacle(const Eigen::Vector2d& p) const;

  std::shared_ptr<const world::PlanarWorld> world_;
  std::vector<int> polygon_first_edge_;  // world_->edges() of polygon i start here
};

}  // namespace amp::nav
