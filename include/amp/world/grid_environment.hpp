#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "amp/world/distance_transform.hpp"
#include "amp/world/environment.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::world {

// Exact geometric queries against a map's obstacles: its blocked squares (occupied or unknown
// cells; unknown space is not driven into) and everything outside the map. All distances are in
// world units to the closed squares. The distance transform answers most disc queries at once; the
// rest scan only the rows within reach, each row's nearest blocked square coming from a table of
// the nearest blocked column to the left and right of every cell. Immutable; no query allocates.
class GridObstacles {
 public:
  explicit GridObstacles(std::shared_ptr<const OccupancyGrid> grid);

  const OccupancyGrid& grid() const { return *grid_; }
  const std::shared_ptr<const OccupancyGrid>& grid_ptr() const { return grid_; }
  const DistanceTransform& distance_transform() const { return edt_; }

  // A disc of radius r at p is free iff it lies inside the map and every blocked square is at
  // distance >= r from p (touching is free).
  bool disc_free(const Eigen::Vector2d& p, double r) const;
  // Distance from p to the nearest blocked square or the map's outside, and the nearest point
  // (0 and p itself when p is in a blocked cell or outside the map).
  double point_distance(const Eigen::Vector2d& p, Eigen::Vector2d& nearest) const;
  // min(point_distance(p), limit), exact: most queries far from every square end at the distance
  // transform's bound, and no row beyond the limit is scanned (a capped clearance, as DWA scores it).
  double point_distance_up_to(const Eigen::Vector2d& p, double limit) const;
  // A polygon (world frame, n >= 3 vertices, simple) is free iff it lies inside the map and its
  // closed region meets no blocked square.
  bool polygon_free(const Eigen::Vector2d* v, int n) const;
  // Distance from a free polygon to the nearest blocked square or the map's outside, with the two
  // closest points; 0 when it is not free.
  double polygon_distance(const Eigen::Vector2d* v, int n, Eigen::Vector2d& robot_point,
                          Eigen::Vector2d& obstacle_point) const;

 private:
  // Nearest blocked square to p among the row's candidates; updates best (squared) and its point.
  void scan_row(const Eigen::Vector2d& p, int cx, int row, double& best_sq, Eigen::Vector2d& best_point) const;
  // point_distance, exact below `limit`; at or beyond it, some distance >= limit.
  double nearest_within(const Eigen::Vector2d& p, double limit, Eigen::Vector2d& nearest) const;
  Eigen::Vector2i clamped_cell(const Eigen::Vector2d& p) const;

  std::shared_ptr<const OccupancyGrid> grid_;
  DistanceTransform edt_;
  Eigen::AlignedBox2d extent_;
  // Per cell: the nearest blocked column at or left of it in its row (-1 if none), and at or right
  // of it (width if none).
  std::vector<std::int32_t> left_;
  std::vector<std::int32_t> right_;
};

// The robot of a map world: a disc (state x, y), a point (state x, y: the robot occupies the cell it
// is in, as MovingAI's benchmarks assume) or a rigid planar body of polygons and circles in its own
// frame (state x, y, theta).
struct GridRobot {
  enum class Kind { kDisc, kPoint, kRigid };
  Kind kind = Kind::kDisc;
  double radius = 0.0;  // disc
  Shapes2d body;        // rigid, body frame
};

// A map world (ROS map_server or MovingAI grid) with a disc or rigid robot. Validity is exact with
// respect to the blocked cells taken as squares; the outside of the map is an obstacle.
class GridEnvironment final : public Environment {
 public:
  // Throws ParameterError for a disc radius <= 0, an empty rigid body, a polygon with fewer than
  // 3 vertices or a circle of radius <= 0.
  GridEnvironment(std::shared_ptr<const OccupancyGrid> grid, GridRobot robot);

  int workspace_dimension() const override { return 2; }
  std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const override;
  Eigen::AlignedBox3d workspace_bounds() const override;
  Outline obstacle_outline() const override;
  Shapes2d robot_outline(const State& s) const override;
  // Blocked cells (unknown ones too, as the checkers take them) as boxes, merged into rectangles,
  // in one mesh; the robot ("body") as its disc, a half-cell disc for a point, or its shapes.
  SceneModel scene_model() const override;
  void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const override;
  Eigen::Vector3d reference_point(const State& s) const override;
  double robot_min_diameter() const override { return min_diameter_; }
  double robot_radius() const override { return radius_; }
  Obstacles2d obstacles_2d() const override { return {nullptr, obstacles_.grid_ptr()}; }
  const GridEnvironment* as_map() const override { return this; }

  const OccupancyGrid& grid() const { return obstacles_.grid(); }
  const GridObstacles& obstacles() const { return obstacles_; }
  const GridRobot& robot() const { return robot_; }
  // Number of coordinates of a state: 2 for a disc or a point, 3 for a rigid body.
  int state_dimension() const { return robot_.kind == GridRobot::Kind::kRigid ? 3 : 2; }

 private:
  GridObstacles obstacles_;
  GridRobot robot_;
  double min_diameter_ = 0.0;
  double radius_ = 0.0;
};

}  // namespace amp::world
