#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace amp::nav {

struct ObstacleChange;
class GridNavWorld;
class PolygonNavWorld;

// The nearest obstacle point to a query point.
struct NearestObstacle {
  double distance = 0.0;                           // 0 when the point is in an obstacle or outside
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // the query point itself in that case
};

// A 2-D world as a mobile robot sees it: obstacles (the outside of the world counts as one), asked
// about a disc robot and about range-sensor rays. Immutable and shared by threads; a change (a door
// that closes) makes a new world. Touching an obstacle is free; all answers are exact.
// Implementations: PolygonNavWorld (polygons, circles, segment walls), GridNavWorld (maps).
class NavWorld {
 public:
  virtual ~NavWorld() = default;

  // The rectangle the robot may use; everything outside it is an obstacle.
  virtual const Eigen::AlignedBox2d& bounds() const = 0;
  // The closed disc of radius r at p meets no obstacle interior and stays inside bounds().
  virtual bool disc_free(const Eigen::Vector2d& p, double r) const = 0;
  // Distance from p to the nearest obstacle (or the outside) and the point where it is.
  virtual NearestObstacle nearest_obstacle(const Eigen::Vector2d& p) const = 0;
  // min(nearest_obstacle(p).distance, limit), exact. Worlds whose exact query costs more the
  // farther the obstacle (a map's row scan) answer a capped one sooner.
  virtual double distance_up_to(const Eigen::Vector2d& p, double limit) const {
    return std::min(nearest_obstacle(p).distance, limit);
  }
  // Distance from p along the unit direction `dir` to the first obstacle or the outside, at most
  // max_range; 0 when p is in an obstacle or outside.
  virtual double ray_cast(const Eigen::Vector2d& p, const Eigen::Vector2d& dir, double max_range) const = 0;
  // This world with `change` applied. Throws ParameterError when it cannot apply (a vanishing
  // shape that is not there, cells on a polygon world, cells outside the map).
  virtual std::shared_ptr<const NavWorld> changed(const ObstacleChange& change) const = 0;

  // This world as a map, or as polygons; null when it is the other kind. A method that needs one
  // kind (policy-search and dwa plan on maps, sins measures a polygon box) takes it typed from here.
  virtual const GridNavWorld* as_map() const { return nullptr; }
  virtual const PolygonNavWorld* as_polygons() const { return nullptr; }

  // Clearance of a disc of radius r at p: distance to the nearest obstacle minus r (< 0: overlap).
  double clearance(const Eigen::Vector2d& p, double r) const { return nearest_obstacle(p).distance - r; }
  // min(clearance(p, r), cap), exact to the bit: the distance is capped at the least limit whose
  // rounded clearance reaches cap, so that every distance beyond it would have given cap too.
  double clearance_up_to(const Eigen::Vector2d& p, double r, double cap) const {
    double limit = r + cap;
    while (limit - r < cap) limit = std::nextafter(limit, std::numeric_limits<double>::infinity());
    return std::min(distance_up_to(p, limit) - r, cap);
  }
};

}  // namespace amp::nav
