#pragma once
#include <memory>

#include <Eigen/Geometry>

#include "amp/core/counters.hpp"
#include "amp/core/state.hpp"
#include "amp/world/shapes2d.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world {

class OccupancyGrid;
class PlanarWorld;

// What `amp render` draws of a world or a robot: shapes in the plane (3-D worlds: their top view,
// i.e. projection on z = 0), and for map worlds the occupancy grid itself.
struct Outline {
  Shapes2d shapes;
  const OccupancyGrid* grid = nullptr;  // owned by the environment; null unless a map world
};

// The obstacles of a 2-D world as data, shared with the environment, for modules that run their
// own geometry on them (nav: ray casting, a robot simulator). At most one is set.
struct Obstacles2d {
  std::shared_ptr<const PlanarWorld> planar;  // polygon / circle / segment worlds (YAML, 2-D .cfg)
  std::shared_ptr<const OccupancyGrid> grid;  // map worlds
};

// A world with a robot in it: makes validity checkers and describes itself for drawing and for
// planners' features. Immutable once built, so one environment serves every thread of a benchmark.
// Implementations: PlanarEnvironment (2-D shapes), SpatialEnvironment (FCL), GridEnvironment (maps).
class Environment {
 public:
  virtual ~Environment() = default;

  // 2 for planar and map worlds, 3 for FCL worlds.
  virtual int workspace_dimension() const = 0;
  // A new checker that counts into `counters`; one per thread.
  virtual std::unique_ptr<ValidityChecker> make_checker(core::Counters& counters) const = 0;
  // Axis-aligned bounds of the workspace (z range 0..0 for planar worlds).
  virtual Eigen::AlignedBox3d workspace_bounds() const = 0;
  // Obstacles as drawn by `amp render`.
  virtual Outline obstacle_outline() const = 0;
  // The robot's footprint at state s, world frame (3-D: top view).
  virtual Shapes2d robot_outline(const State& s) const = 0;
  // Position of the robot's reference point (UAS features X, Y, Z; the end effector for arms).
  virtual Eigen::Vector3d reference_point(const State& s) const = 0;
  // Smallest diameter of the robot (Gaussian sampler distance d = r in UAS).
  virtual double robot_min_diameter() const = 0;
  // Largest distance of a robot point from its reference frame origin (metric weight of rotations).
  virtual double robot_radius() const = 0;
  // The obstacles of a 2-D world; both null for 3-D worlds.
  virtual Obstacles2d obstacles_2d() const { return {}; }
};

}  // namespace amp::world
