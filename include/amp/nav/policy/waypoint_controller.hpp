#pragma once
#include <cstddef>
#include <limits>
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
  // rad: a heading error above this is turned on the spot (v = 0), and a waypoint whose turn is
  // larger is stopped at and switched from once passed, as a footprint certified turning in place
  // at the waypoints must be driven (Nav2's Regulated Pure Pursuit rotates to heading likewise).
  // Infinite: never, v = v_ref max(0, cos e) as the paper's controller.
  double turn_in_place = std::numeric_limits<double>::infinity();
  // m: the pure-pursuit aim ahead of the projection on the segment; 0 means d_approach.
  double lookahead = 0.0;
  // Throws ParameterError naming the setting unless d_approach, heading_gain, goal_tolerance and
  // accel are > 0 and finite, turn_in_place > 0 and lookahead >= 0 and finite.
  void validate() const;
};

// The local controller of a waypoint policy ("Policy search seeded by a value function", eqs. 2-3):
// it drives the segment w_j-1 -> w_j and switches to w_j+1 once ||s - w_j|| < d_approach (eq. 3).
// Command (v, omega): omega = heading_gain * e, e the heading error (wrapped to [-pi, pi)) toward
// the point d_approach ahead of the robot's projection on the segment (pure pursuit; w_0 itself
// before the first switch), and v = v_ref max(0, cos e), so the robot turns on the spot when the
// aim is behind it; v_ref is the speed PolicyValue assumed at that progress (linear between the two
// waypoints' speeds). Toward the last waypoint v is also capped at sqrt(2 accel d) so that it can
// stop there. Waypoints are 5-D (x, y, theta, v, omega; core::UnicycleSpace's layout); their
// heading and turn rate are what the search shapes the path with, not set points. Driven on a
// simulator, a refused move (the footprint touched an obstacle) sends it back to the waypoint
// before the current one; within goal_tolerance of it, it resumes. With a finite turn_in_place,
// waypoints where the path turns by more are driven to and turned at on the spot (see the setting).
class WaypointController final : public MotionController {
 public:
  // Throws ParameterError for bad settings or no waypoints.
  WaypointController(std::vector<State> waypoints, WaypointControllerSettings settings = {});

  // The command for the robot at s; first advances past every waypoint within d_approach (eq. 3;
  // the last one is never passed).
  Eigen::Vector2d command(const RobotState& s);
  Eigen::Vector2d command(const Simulator& sim) override;
  // Index of the waypoint steered to (the one after it while retreating).
  std::size_t current() const { return current_; }
  // Going back to the waypoint before current() after the footprint touched an obstacle.
  bool retreating() const { return retreating_; }
  // Within goal_tolerance of the last waypoint.
  bool arrived(const RobotState& s) const override;
  const std::vector<State>& waypoints() const { return waypoints_; }

 private:
  // How far the path turns at waypoint j (0 at the ends), and whether the robot at s has reached it.
  double turn_at(std::size_t j) const;
  bool reached(const RobotState& s, std::size_t j) const;
  // (v, omega) toward `aim` at up to v_ref, and slow enough to stop within brake_distance.
  Eigen::Vector2d steer(const RobotState& s, const Eigen::Vector2d& aim, double v_ref, double brake_distance) const;

  std::vector<State> waypoints_;
  WaypointControllerSettings settings_;
  std::size_t current_ = 0;
  bool retreating_ = false;
  std::size_t blocked_seen_ = 0;  // the simulator's refused moves seen so far
};

}  // namespace amp::nav
