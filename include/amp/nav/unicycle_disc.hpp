#pragma once
#include "amp/nav/robot_model.hpp"

namespace amp::nav {

// Limits of a differential-drive robot. Defaults: Nav2's DWB reference configuration
// (nav2_params.yaml: max_vel_x 0.26, min_vel_x 0, max_vel_theta 1.0, acc_lim_x 2.5,
// acc_lim_theta 3.2) and the disc of the policy-search paper's robot, 54 cm across with its margin.
struct UnicycleDiscSettings {
  double radius = 0.27;     // m
  double v_min = 0.0;       // m/s (< 0 allows reversing)
  double v_max = 0.26;      // m/s
  double omega_max = 1.0;   // rad/s, either way
  double accel = 2.5;       // m/s^2, either way
  double alpha = 3.2;       // rad/s^2, either way
  // m along the heading: 0 for the disc; else the footprint is a rectangle this long and 2 radius
  // wide (Footprint::rectangle), checked at the robot's heading.
  double length = 0.0;
  // Throws ParameterError naming the setting unless radius, v_max, omega_max, accel and alpha are
  // > 0 and v_min <= 0, all finite, and length is 0 or at least 2 radius.
  void validate() const;
};

// A disc with unicycle kinematics: state (x, y, theta) and velocities (v, omega) in
// RobotState::velocity; a command is the velocity pair it steers to, clipped to the limits. The
// velocities move toward the command at the acceleration limits, then hold, so over a step each is
// piecewise linear in time; the pose is the exact integral (an arc once both velocities hold, and
// Simpson's rule on the short ramps before, where the heading is quadratic in time).
class UnicycleDisc final : public RobotModel {
 public:
  explicit UnicycleDisc(UnicycleDiscSettings settings = {});

  const UnicycleDiscSettings& settings() const { return settings_; }
  // (v, omega) clipped to the velocity limits; (0, 0) for a command that is not finite.
  Eigen::Vector2d clipped(const Eigen::Vector2d& command) const;

  double radius() const override { return settings_.radius; }
  RobotState propagate(const RobotState& s, const Eigen::Vector2d& command, double t) const override;
  // The largest |v| over the ramp: the larger of |v| now and the clipped command's.
  double speed_bound(const RobotState& s, const Eigen::Vector2d& command) const override;
  Footprint footprint() const override;
  double turn_bound(const RobotState& s, const Eigen::Vector2d& command) const override;

 private:
  UnicycleDiscSettings settings_;
};

}  // namespace amp::nav
