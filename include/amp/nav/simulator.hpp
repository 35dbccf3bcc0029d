#pragma once
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/range_sensor_ring.hpp"
#include "amp/nav/robot_model.hpp"
#include "amp/nav/world_timeline.hpp"

namespace amp::core {
class Rng;
}

namespace amp::nav {

// What one step did.
struct StepResult {
  bool blocked = false;         // the move was cut short (or not made) by an obstacle
  bool trapped = false;         // an obstacle that appeared overlaps the robot: it cannot move
  bool world_changed = false;   // events took effect at the start of this step
  double travelled = 0.0;       // straight distance from the old to the new position
};

struct SimulatorSettings {
  double time_step = 0.1;  // s
  // Closer than this to an obstacle the robot is in contact: it only moves where a step of this
  // length gains clearance (so it backs off, but does not graze along a wall). Must be < radius.
  double contact_tolerance = 1e-6;  // m
  // Advancement iterations per step before the move counts as blocked.
  int max_advances = 64;
  RangeSensorSettings sensors{};
  // Throws ParameterError for a non-positive time step or tolerance, max_advances < 1, or bad sensors.
  void validate() const;
};

// A fixed-time-step simulation of one disc robot in a changing 2-D world. Each step: the events of
// that step take effect; the robot moves under its command for one time step, by conservative
// advancement (each advance no longer than the clearance, so no obstacle, however thin, is ever
// crossed); a move that would overlap an obstacle stops at the last free position reached and
// counts as blocked; then the sensors read. Randomness (sensor noise) comes from the caller's Rng.
//
// Obstacles that appear on the robot are applied anyway: the robot is then trapped (every move is
// blocked and counted) until they vanish, as a robot pinned by a closing door would be.
class Simulator {
 public:
  // Throws ParameterError for null parts, bad settings, a tolerance >= the robot's radius, or a
  // start where the disc is not free in the world of step 0.
  Simulator(std::shared_ptr<const WorldTimeline> timeline, std::shared_ptr<const RobotModel> robot, RobotState start,
            SimulatorSettings settings = {});

  StepResult step(const Eigen::Vector2d& command, core::Rng& rng);
  // Puts the robot at `s` (a new query's start), at rest; the clock goes on. Throws ParameterError
  // when the disc is not free there in the world of the next step.
  void place(const RobotState& s);
  // The world the next step runs in.
  const NavWorld& next_world() const { return *timeline_->at(steps_); }

  const RobotState& state() const { return state_; }
  // Readings of the last step (max_range everywhere before the first).
  std::span<const double> ranges() const { return ranges_; }
  const NavWorld& world() const { return *timeline_->at(steps_ == 0 ? 0 : steps_ - 1); }
  const RobotModel& robot() const { return *robot_; }
  const Footprint& footprint() const { return footprint_; }
  const RangeSensorRing& sensors() const { return sensors_; }
  std::size_t step_count() const { return steps_; }
  std::size_t blocked_moves() const { return blocked_; }
  double time_step() const { return settings_.time_step; }
  double time() const { return static_cast<double>(steps_) * settings_.time_step; }

 private:
  // Moves state_ through one time step in `world`; true when the move was cut short.
  bool move(const NavWorld& world, const Eigen::Vector2d& command);

  std::shared_ptr<const WorldTimeline> timeline_;
  std::shared_ptr<const RobotModel> robot_;
  SimulatorSettings settings_;
  RangeSensorRing sensors_;
  RobotState state_;
  Footprint footprint_;  // the robot's, fixed for the run
  std::vector<double> ranges_;
  std::size_t steps_ = 0;
  std::size_t blocked_ = 0;
  std::size_t version_ = 0;
};

}  // namespace amp::nav
