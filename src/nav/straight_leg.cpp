#include "amp/nav/straight_leg.hpp"

#include <algorithm>
#include <cmath>

#include "amp/core/stop_condition.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

namespace {

// Whether a sensor sees an obstacle that the disc, driving along `dir` for `remaining`, would hit
// first: the reading's point lies within the swept band (lateral offset < r) and before the end.
bool sensed_block(const Simulator& sim, const Eigen::Vector2d& dir, double remaining, double block_distance) {
  if (block_distance <= 0.0) return false;
  const double r = sim.robot().radius();
  const auto ranges = sim.ranges();
  for (int i = 0; i < sim.sensors().count(); ++i) {
    const double reading = ranges[static_cast<std::size_t>(i)];
    if (reading >= block_distance || reading >= sim.sensors().settings().max_range) continue;
    const Eigen::Vector2d hit = (r + reading) * sim.sensors().direction(i, sim.state().heading);
    const double ahead = hit.dot(dir);
    const double lateral = std::abs(hit.x() * dir.y() - hit.y() * dir.x());
    if (ahead > 0.0 && lateral < r && ahead - r < remaining) return true;
  }
  return false;
}

}  // namespace

LegResult drive_straight(Simulator& sim, const Eigen::Vector2d& to, double speed, const StraightLegSettings& settings,
                         core::Rng& rng, const core::StopCondition* stop, std::vector<Eigen::Vector2d>* trace) {
  LegResult out;
  const double length = (to - sim.state().position).norm();
  const double scale = std::max(1.0, to.cwiseAbs().maxCoeff());
  const double arrive = 1e-9 * scale;
  const auto budget = static_cast<std::size_t>(std::ceil(settings.budget_factor * length / speed)) +
                      static_cast<std::size_t>(settings.stall_steps);
  double best = length;  // closest distance to `to` so far
  int stalled = 0;
  const double step_time = sim.time_step();
  for (;;) {
    const Eigen::Vector2d gap = to - sim.state().position;
    const double remaining = gap.norm();
    if (remaining <= arrive) return out;
    if (out.steps >= budget) {
      out.end = LegEnd::kBlocked;
      return out;
    }
    if (stop != nullptr && stop->time_up()) {
      out.end = LegEnd::kStopped;
      return out;
    }
    const Eigen::Vector2d dir = gap / remaining;
    if (sensed_block(sim, dir, remaining, settings.block_distance)) {
      out.end = LegEnd::kBlocked;
      return out;
    }
    // A velocity that covers the rest exactly when it is shorter than one step at full speed.
    const Eigen::Vector2d command = dir * (std::min(speed, remaining) / step_time);
    const StepResult r = sim.step(command, rng);
    ++out.steps;
    out.travelled += r.travelled;
    if (trace != nullptr) trace->push_back(sim.state().position);
    if (r.blocked) {
      out.end = LegEnd::kBlocked;
      return out;
    }
    const double now = (to - sim.state().position).norm();
    if (now < best - 1e-12 * scale) {
      best = now;
      stalled = 0;
    } else if (++stalled >= settings.stall_steps) {
      out.end = LegEnd::kBlocked;
      return out;
    }
  }
}

}  // namespace amp::nav
