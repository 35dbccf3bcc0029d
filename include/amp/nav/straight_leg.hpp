#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace amp::core {
class Rng;
class StopCondition;
}  // namespace amp::core

namespace amp::nav {

class Simulator;

struct StraightLegSettings {
  double block_distance = 0.0;  // a reading ahead below this (and before the end) is a block; 0: touch only
  int stall_steps = 20;         // this many steps without progress is a block
  double budget_factor = 3.0;   // at most this many times the unobstructed step count (+ stall_steps)
  // Distance the robot may travel off the straight line, sliding past what blocks it; 0: none (a
  // block ends the leg at once).
  double detour = 0.0;
};

enum class LegEnd { kArrived, kBlocked, kStopped };

struct LegResult {
  LegEnd end = LegEnd::kArrived;
  double travelled = 0.0;
  std::size_t steps = 0;
};

// Drives a holonomic disc (a velocity command) straight to `to` at most at `speed` per time step,
// and reports a block the way a robot perceives one: the simulator stopped a move (touch), a range
// sensor pointing along the way reads an obstacle nearer than block_distance that the disc would
// sweep before arriving, or the robot makes no progress. Positions go to `trace` when given.
// Stops with kStopped when `stop` fires.
// With a detour allowance the robot, instead of stopping at a block, steps in the nearest direction
// (20 degrees at a time, up to 80, on the side it last turned to first) that no sensor sees blocked
// and that the simulator lets it move; it must still get nearer the end (stall_steps), and the leg is
// blocked once the steps off the line add up to more than the allowance. A leg that grazes a door
// frame slides past it; a wall between the ends still blocks.
LegResult drive_straight(Simulator& sim, const Eigen::Vector2d& to, double speed, const StraightLegSettings& settings,
                         core::Rng& rng, const core::StopCondition* stop, std::vector<Eigen::Vector2d>* trace);

// Drives back through `path` (positions the robot passed, each a step from the next, ending where it
// stands), from its end to its front, without sliding: the way back is the way it came. kArrived at
// path.front(); kBlocked if a step of the way is refused (sensor noise); kStopped when `stop` fires.
// `path` must not alias `trace`.
LegResult drive_back(Simulator& sim, std::span<const Eigen::Vector2d> path, double speed, core::Rng& rng,
                     const core::StopCondition* stop, std::vector<Eigen::Vector2d>* trace);

}  // namespace amp::nav
