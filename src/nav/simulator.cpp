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
      state_(start),
      footprint_(robot_ ? robot_->footprint() : Footprint::disc(1.0)) {
  settings_.validate();
  if (!timeline_ || !robot_) throw ParameterError("simulator: no world or no robot");
  // A contact step of at most the radius never carries the disc across a wall of no thickness.
  if (settings_.contact_tolerance >= robot_->radius()) {
    throw ParameterError("simulator: contact_tolerance " + std::to_string(settings_.contact_tolerance) +
                         " must be smaller than the robot's radius " + std::to_string(robot_->radius()));
  }
  if (!footprint_.free(*timeline_->at(0), state_.position, state_.heading)) {
    throw ParameterError("simulator: the robot's start (" + std::to_string(state_.position.x()) + ", " +
                         std::to_string(state_.position.y()) + ") is in an obstacle or outside the world");
  }
  ranges_.assign(static_cast<std::size_t>(sensors_.count()), settings_.sensors.max_range);
}

void Simulator::place(const RobotState& s) {
  if (!footprint_.free(next_world(), s.position, s.heading)) {
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
  if (!footprint_.free(w, state_.position, state_.heading)) {
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
  const double total = settings_.time_step, tol = settings_.contact_tolerance;
  const RobotState s0 = state_;
  // Any disc of the footprint moves no faster than the centre plus its reach times the turn rate.
  const double speed = robot.speed_bound(s0, command) + footprint_.centre_reach() * robot.turn_bound(s0, command);
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
    const double c = footprint_.clearance(w, current.position, current.heading);
    if (c < 0.0 || !footprint_.free(w, current.position, current.heading)) break;
    last_free = current;
    if (c < tol) {
      // In contact: one short step, kept only when it leaves the obstacle behind.
      const double h = std::min(total - t, tol / speed);
      const RobotState probe = robot.propagate(s0, command, t + h);
      if (!footprint_.free(w, probe.position, probe.heading) ||
          footprint_.clearance(w, probe.position, probe.heading) <= c) {
        break;
      }
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
      if (!footprint_.free(w, end.position, end.heading)) break;  // touching, up to rounding
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
