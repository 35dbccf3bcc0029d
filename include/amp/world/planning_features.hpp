#pragma once
#include <Eigen/Geometry>

#include "amp/core/state.hpp"

namespace amp::world {

// The role of a world that planners read beside the checker: its extent and the robot's size and
// reference point (UAS's features, the offset samplers' distances, region boxes).
class PlanningFeatures {
 public:
  virtual ~PlanningFeatures() = default;
  // 2 for planar and map worlds, 3 for FCL worlds.
  virtual int workspace_dimension() const = 0;
  // Axis-aligned bounds of the workspace (z range 0..0 for planar worlds).
  virtual Eigen::AlignedBox3d workspace_bounds() const = 0;
  // Position of the robot's reference point (UAS features X, Y, Z; the end effector for arms).
  virtual Eigen::Vector3d reference_point(const State& s) const = 0;
  // Smallest diameter of the robot (Gaussian sampler distance d = r in UAS).
  virtual double robot_min_diameter() const = 0;
  // Largest distance of a robot point from its reference frame origin (metric weight of rotations).
  virtual double robot_radius() const = 0;
};

}  // namespace amp::world
