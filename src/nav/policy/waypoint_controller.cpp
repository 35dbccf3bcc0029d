#include "amp/nav/policy/waypoint_controller.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

void WaypointControllerSettings::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw ParameterError(std::string(name) + " must be > 0, got " + std::to_string(v));
    }
  };
  positive(d_approach, "d_approach");
  positive(heading_gain, "heading_gain");
  positive(goal_tolerance, "goal_tolerance");
  positive(accel, "accel");
}

WaypointController::WaypointController(std::vector<State> waypoints, WaypointControllerSettings settings)
    : waypoints_(std::move(waypoints)), settings_(settings) {
  settings_.validate();
  if (waypoints_.empty()) throw ParameterError("a waypoint policy needs at least one waypoint");
}

namespace {
Eigen::Vector2d xy(const State& w) { return {w[0], w[1]}; }
}  // namespace

Eigen::Vector2d WaypointController::command(const RobotState& s) {
  while (current_ + 1 < waypoints_.size() && (s.position - xy(waypoints_[current_])).norm() < settings_.d_approach) {
    ++current_;
  }
  const State& w = waypoints_[current_];
  const Eigen::Vector2d to = xy(w) - s.position;
  const double dist = to.norm();
  const bool last = current_ + 1 == waypoints_.size();
  if (last && dist < settings_.goal_tolerance) return Eigen::Vector2d::Zero();
  const double e = core::angle_difference(s.heading, std::atan2(to.y(), to.x()));
  double v = w[3] * std::max(0.0, std::cos(e));
  if (last) v = std::min(v, std::sqrt(2.0 * settings_.accel * dist));
  return {v, settings_.heading_gain * e};
}

Eigen::Vector2d WaypointController::command(const Simulator& sim) { return command(sim.state()); }

bool WaypointController::arrived(const RobotState& s) const {
  return (s.position - xy(waypoints_.back())).norm() < settings_.goal_tolerance;
}

}  // namespace amp::nav
