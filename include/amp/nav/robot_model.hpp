#pragma once
#include <Eigen/Core>

#include "amp/nav/footprint.hpp"

namespace amp::nav {

// What the simulator knows of a robot: its pose and the model's own velocity coordinates.
struct RobotState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double heading = 0.0;                              // rad; the sensor ring turns with it
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // holonomic: (vx, vy); a unicycle: (v, omega)
};

// The kinematics of a disc robot, as the step simulator drives it. Implementations: HolonomicDisc
// (a velocity command); a unicycle (v, omega with acceleration limits) plugs in the same way.
class RobotModel {
 public:
  virtual ~RobotModel() = default;

  // Radius of the robot's disc.
  virtual double radius() const = 0;
  // The state after time t >= 0 from s under `command`, ignoring obstacles; continuous in t.
  virtual RobotState propagate(const RobotState& s, const Eigen::Vector2d& command, double t) const = 0;
  // A bound on the centre's speed while propagate() runs from s under `command` (the conservative
  // advancement needs it); 0 when the robot stays put.
  virtual double speed_bound(const RobotState& s, const Eigen::Vector2d& command) const = 0;
  // What collides: the disc of radius() unless the model says otherwise (a rectangle at the heading).
  virtual Footprint footprint() const { return Footprint::disc(radius()); }
  // A bound on |d heading / dt| over the same run, for a footprint whose discs are off the centre.
  virtual double turn_bound(const RobotState&, const Eigen::Vector2d&) const { return 0.0; }
};

}  // namespace amp::nav
