#pragma once
#include "amp/nav/robot_model.hpp"

namespace amp::nav {

struct HolonomicDiscSettings {
  double radius = 0.0275;  // m: Khepera, 55 mm across
  double max_speed = 0.1;  // m/s
  // Throws ParameterError unless radius > 0 and max_speed > 0 (both finite).
  void validate() const;
};

// A disc that moves in any direction at the commanded velocity (vx, vy), world frame, clipped to a
// maximum speed; its heading does not change. Default: Khepera-like, 55 mm across.
class HolonomicDisc final : public RobotModel {
 public:
  explicit HolonomicDisc(HolonomicDiscSettings settings = {});

  const HolonomicDiscSettings& settings() const { return settings_; }
  // The command clipped to the maximum speed (direction kept).
  Eigen::Vector2d clipped(const Eigen::Vector2d& command) const;

  double radius() const override { return settings_.radius; }
  RobotState propagate(const RobotState& s, const Eigen::Vector2d& command, double t) const override;
  double speed_bound(const RobotState&, const Eigen::Vector2d& command) const override {
    return clipped(command).norm();
  }

 private:
  HolonomicDiscSettings settings_;
};

}  // namespace amp::nav
