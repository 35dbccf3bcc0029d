#include "amp/nav/holonomic_disc.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::nav {

void HolonomicDiscSettings::validate() const {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw ParameterError("holonomic disc: radius must be > 0, got " + std::to_string(radius));
  }
  if (!(max_speed > 0.0) || !std::isfinite(max_speed)) {
    throw ParameterError("holonomic disc: max_speed must be > 0, got " + std::to_string(max_speed));
  }
}

HolonomicDisc::HolonomicDisc(HolonomicDiscSettings settings) : settings_(settings) { settings_.validate(); }

Eigen::Vector2d HolonomicDisc::clipped(const Eigen::Vector2d& command) const {
  if (!command.allFinite()) return Eigen::Vector2d::Zero();
  const double speed = command.norm();
  return speed > settings_.max_speed ? Eigen::Vector2d(command * (settings_.max_speed / speed)) : command;
}

RobotState HolonomicDisc::propagate(const RobotState& s, const Eigen::Vector2d& command, double t) const {
  RobotState out = s;
  out.velocity = clipped(command);
  out.position += t * out.velocity;
  return out;
}

}  // namespace amp::nav
