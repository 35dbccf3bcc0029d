#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "amp/core/state.hpp"
#include "amp/nav/motion_controller.hpp"
#include "amp/nav/robot_model.hpp"

namespace amp::nav {

struct WaypointControllerSettings {
  double d_approach = 0.3;      // m: within this of the current waypoint, switch to the next (eq. 3)
  double heading_gain = 2.5;    // 1/s: turn rate per radian of heading error
  double goal_tolerance = 0.1;  // m: within this of the last waypoint, the policy has arrived
  double accel = 2.5;           // m/s^2 the robot can brake at: it slows to stop at the last waypoint
  // Throws ParameterError naming the setting unless all are > 0 and finite.
  void validate() const;
};

// The local controller of a waypoint policy ("Policy search seeded by a value function", eqs. 2-3):
// it steers toward the current waypoint w_j and switches to w_j+1 once ||s - w_j|| < d_approach.
// Command (v, omega): omega = heading_gain * e, e the heading error toward w_j (wrapped to
// [-pi, pi)), and v = v_j max(0, cos e) with v_j the waypoint's speed, so the robot turns on the
// spot when w_j is behind it; toward the last waypoint v is also capped at sqrt(2 accel d) so that
// it can stop there. Waypoints are 5-D (x, y, theta, v, omega; core::UnicycleSpace's layout);
// their heading and turn rate are what the search shapes the path with, not set points.
class WaypointController final : public MotionController {
 public:
  // Throws ParameterError for bad settings or no waypoints.
  WaypointController(std::vector<State> waypoints, WaypointControllerSettings settings = {});

  // The command for the robot at s; first advances past every waypoint within d_approach (eq. 3;
  // the last one is never passed).
  Eigen::Vector2d command(const RobotState& s);
  Eigen::Vector2d command(const Simulator& sim) override;
  // Index of the waypoint steered to.
  std::size_t current() const { return current_; }
  // Within goal_tolerance of the last waypoint.
  bool arrived(const RobotState& s) const override;
  const std::vector<State>& waypoints() const { return waypoints_; }

 private:
  std::vector<State> waypoints_;
  WaypointControllerSettings settings_;
  std::size_t current_ = 0;
};

}  // namespace amp::nav
