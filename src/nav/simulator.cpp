#include "amp/nav/simulator.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::nav {

void SimulatorSettings::validate() const {
  if (!(time_step > 0.0) || !std::isfinite(time_step)) {
    throw ParameterError("simulator: time_step must be > 0, got " + std::to_string(time_step));
  }
  if (!(contact_tolerance > 0.0) || !std::isfinite(contact_tolerance)) {
    throw ParameterError("simulator: contact_tolerance must be > 0, got " + std::to_string(contact_tolerance));
  }
  if (max_advances < 1) throw ParameterError("simulator: max_advances must be >= 1, got " + std::to_string(max_advances));
  sensors.validate();
}

Simulator::Simulator(std::shared_ptr<const WorldTimeline> timeline, std::shared_ptr<const RobotModel> robot,
                     RobotState start, SimulatorSettings settings)
    : timeline_(std::move(timeline)),
      robot_(std::move(robot)),
      settings_(settings),
      sensors_(settings_.sensors),
      state_(start) {
  settings_.validate();
  if (!timeline_ || !robot_) throw ParameterError("simulator: no world or no robot");
  // A contact step of at most the radius never carries the disc across a wall of no thickness.
  if (settings_.contact_tolerance >= robot_->radius()) {
    throw ParameterError("simulator: contact_tolerance " + std::to_string(settings_.contact_tolerance) +
                         " must be smaller than the robot's radius " + std::to_string(robot_->radius()));
  }
  if (!timeline_->at(0)->disc_free(state_.position, robot_->radius())) {
    throw ParameterError("simulator: the robot's start (" + std::to_string(state_.position.x()) + ", " +
                         std::to_string(state_.position.y()) + ") is in an obstacle or outside the world");
  }
  ranges_.assign(static_cast<std::size_t>(sensors_.count()), settings_.sensors.max_range);
}

void Simulator::place(const RobotState& s) {
  if (!next_world().disc_free(s.position, robot_->radius())) {
    throw ParameterError("simulator: the robot cannot be placed at (" + std::to_string(s.position.x()) + ", " +
                         std::to_string(s.position.y()) + "): in an obstacle or outside the world");
  }
  state_ = s;
  state_.velocity.setZero();
  ranges_.assign(ranges_.size(), settings_.sensors.max_range);
}

StepResult Simulator::step(const Eigen::Vector2d& command, core::Rng& rng) {
  StepResult result;
  const std::size_t version = timeline_->version_at(steps_);
  result.world_changed = version != version_;
  version_ = version;
  const NavWorld& w = *timeline_->at(steps_);
  const Eigen::Vector2d before = state_.position;
  if (!w.disc_free(state_.position, robot_->radius())) {
    result.trapped = result.blocked = true;  // an obstacle appeared on the robot
    state_.velocity.setZero();
  } else {
    result.blocked = move(w, command);
  }
  if (result.blocked) ++blocked_;
  result.travelled = (state_.position - before).norm();
  sensors_.read(w, state_, robot_->radius(), rng, ranges_);
  ++steps_;
  return result;
}

bool Simulator::move(const NavWorld& w, const Eigen::Vector2d& command) {
  const RobotModel& robot = *robot_;
  const double r = robot.radius(), total = settings_.time_step, tol = settings_.contact_tolerance;
  const RobotState s0 = state_;
  const double speed = robot.speed_bound(s0, command);
  if (!(speed > 0.0)) {
    state_ = robot.propagate(s0, command, total);  // standing still: the pose cannot change
    state_.position = s0.position;
    return false;
  }
  // Conservative advancement: over time c / speed the centre moves at most c, the clearance, so the
  // disc stays free. `last_free` is the last state whose disc was checked free.
  RobotState current = s0, last_free = s0;
  double t = 0.0;
  for (int i = 0; i < settings_.max_advances; ++i) {
    const double c = w.clearance(current.position, r);
    if (c < 0.0 || !w.disc_free(current.position, r)) break;
    last_free = current;
    if (c < tol) {
      // In contact: one short step, kept only when it leaves the obstacle behind.
      const double h = std::min(total - t, tol / speed);
      const RobotState probe = robot.propagate(s0, command, t + h);
      if (!w.disc_free(probe.position, r) || w.clearance(probe.position, r) <= c) break;
      t += h;
      current = probe;
      if (t >= total) {
        state_ = current;
        return false;
      }
      continue;
    }
    if (t + c / speed >= total) {
      const RobotState end = robot.propagate(s0, command, total);
      if (!w.disc_free(end.position, r)) break;  // touching, up to rounding
      state_ = end;
      return false;
    }
    t += c / speed;
    current = robot.propagate(s0, command, t);
  }
  state_ = last_free;
  state_.velocity.setZero();
  return true;
}

}  // namespace amp::nav
