#include "amp/nav/policy/waypoint_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
  if (!(turn_in_place > 0.0)) throw ParameterError("turn_in_place must be > 0, got " + std::to_string(turn_in_place));
  if (!(lookahead >= 0.0) || !std::isfinite(lookahead)) {
    throw ParameterError("lookahead must be >= 0, got " + std::to_string(lookahead));
  }
}

WaypointController::WaypointController(std::vector<State> waypoints, WaypointControllerSettings settings)
    : waypoints_(std::move(waypoints)), settings_(settings) {
  settings_.validate();
  if (waypoints_.empty()) throw ParameterError("a waypoint policy needs at least one waypoint");
}

namespace {
Eigen::Vector2d xy(const State& w) { return {w[0], w[1]}; }
}  // namespace

double WaypointController::turn_at(std::size_t j) const {
  if (j == 0 || j + 1 >= waypoints_.size()) return 0.0;
  const Eigen::Vector2d in = xy(waypoints_[j]) - xy(waypoints_[j - 1]), out = xy(waypoints_[j + 1]) - xy(waypoints_[j]);
  if (in.squaredNorm() == 0.0 || out.squaredNorm() == 0.0) return 0.0;
  return std::abs(core::angle_difference(std::atan2(in.y(), in.x()), std::atan2(out.y(), out.x())));
}

bool WaypointController::reached(const RobotState& s, std::size_t j) const {
  if ((s.position - xy(waypoints_[j])).norm() < settings_.d_approach) return true;
  // A waypoint turned at on the spot is also reached once passed: noise may keep the robot a little
  // beside it, and it must not drive on looking for it.
  if (j == 0 || turn_at(j) <= settings_.turn_in_place) return false;
  const Eigen::Vector2d seg = xy(waypoints_[j]) - xy(waypoints_[j - 1]);
  return (s.position - xy(waypoints_[j])).dot(seg) >= 0.0;
}

Eigen::Vector2d WaypointController::command(const RobotState& s) {
  // A retreat ends at the passed waypoint itself (not within d_approach of it), so that the robot
  // sets off again from where the policy's segment begins.
  if (retreating_ && (s.position - xy(waypoints_[current_ - 1])).norm() < settings_.goal_tolerance) retreating_ = false;
  while (!retreating_ && current_ + 1 < waypoints_.size() && reached(s, current_)) ++current_;
  if (retreating_) {
    const State& back = waypoints_[current_ - 1];
    return steer(s, xy(back), back[3], (xy(back) - s.position).norm());
  }
  const State& w = waypoints_[current_];
  const bool last = current_ + 1 == waypoints_.size();
  const double to_w = (xy(w) - s.position).norm();
  if (last && to_w < settings_.goal_tolerance) return Eigen::Vector2d::Zero();
  const double brake = last || turn_at(current_) > settings_.turn_in_place ? to_w : std::numeric_limits<double>::infinity();
  if (current_ == 0) return steer(s, xy(w), w[3], brake);
  // On a segment: the speed the policy's value assumed at the robot's progress (PolicyValue
  // interpolates it between the waypoints' speeds), and the aim d_approach further along the
  // segment (pure pursuit), so that the robot converges onto the segment the search scored: a
  // door's segment is lined up with the door, where pointing at w_j alone would enter it askew.
  const State& from = waypoints_[current_ - 1];
  const Eigen::Vector2d seg = xy(w) - xy(from);
  const double len = seg.norm();
  if (len == 0.0) return steer(s, xy(w), w[3], brake);
  const double t = std::clamp((s.position - xy(from)).dot(seg) / (len * len), 0.0, 1.0);
  const double ahead = settings_.lookahead > 0.0 ? settings_.lookahead : settings_.d_approach;
  const Eigen::Vector2d aim = xy(from) + std::min(1.0, t + ahead / len) * seg;
  return steer(s, aim, from[3] + t * (w[3] - from[3]), brake);
}

Eigen::Vector2d WaypointController::steer(const RobotState& s, const Eigen::Vector2d& aim, double v_ref,
                                          double brake_distance) const {
  const Eigen::Vector2d to = aim - s.position;
  const double e = core::angle_difference(s.heading, std::atan2(to.y(), to.x()));
  double v = std::abs(e) > settings_.turn_in_place ? 0.0 : v_ref * std::max(0.0, std::cos(e));
  v = std::min(v, std::sqrt(2.0 * settings_.accel * brake_distance));
  return {v, settings_.heading_gain * e};
}

Eigen::Vector2d WaypointController::command(const Simulator& sim) {
  // A refused move means the footprint touched an obstacle (a door frame, under noise): pushing on
  // would pin it there, so go back to the waypoint already passed, in free space, and try again
  // (a retreat, like Nav2's back-up recovery, for a robot that cannot reverse).
  if (sim.blocked_moves() > blocked_seen_) {
    blocked_seen_ = sim.blocked_moves();
    if (current_ > 0 && !retreating_) retreating_ = true;
  }
  return command(sim.state());
}

bool WaypointController::arrived(const RobotState& s) const {
  return (s.position - xy(waypoints_.back())).norm() < settings_.goal_tolerance;
}

}  // namespace amp::nav
