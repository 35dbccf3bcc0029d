#pragma once
#include <Eigen/Core>

#include "amp/nav/robot_model.hpp"

namespace amp::nav {

class Simulator;

// A local controller that drives a robot model step by step: the command for the state the
// simulator is in, and whether the robot has arrived. Implementations: WaypointController (a
// policy-search policy, eq. 3), DynamicWindow (Fox, Burgard & Thrun 1997).
class MotionController {
 public:
  virtual ~MotionController() = default;
  // The command (the robot model's own, e.g. (v, omega) for a unicycle) for the simulator's state;
  // may read its sensors and world.
  virtual Eigen::Vector2d command(const Simulator& sim) = 0;
  virtual bool arrived(const RobotState& s) const = 0;
};

}  // namespace amp::nav
