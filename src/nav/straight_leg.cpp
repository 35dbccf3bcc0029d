#include "amp/nav/straight_leg.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  constexpr int kTurns = 4;                                 // directions tried each side of the line
  constexpr double kTurn = 20.0 * std::numbers::pi / 180.0;  // between them
  LegResult out;
  const double length = (to - sim.state().position).norm();
  const double scale = std::max(1.0, to.cwiseAbs().maxCoeff());
  const double arrive = 1e-9 * scale;
  const auto budget = static_cast<std::size_t>(std::ceil(settings.budget_factor * length / speed)) +
                      static_cast<std::size_t>(settings.stall_steps);
  const int candidates = settings.detour > 0.0 ? 1 + 2 * kTurns : 1;
  double best = length;  // closest distance to `to` so far
  int stalled = 0;
  double detoured = 0.0;
  int side = 1;                 // the side tried first: the one last turned to
  unsigned refused = 0;         // candidates the simulator stopped at `refused_at`
  Eigen::Vector2d refused_at = sim.state().position;
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
    if ((sim.state().position - refused_at).squaredNorm() > arrive * arrive) refused = 0;
    const Eigen::Vector2d dir = gap / remaining;
    int chosen = -1;
    double angle = 0.0;
    Eigen::Vector2d heading = dir;
    for (int c = 0; c < candidates && chosen < 0; ++c) {
      if ((refused >> c) & 1U) continue;
      angle = c == 0 ? 0.0 : side * ((c + 1) / 2) * kTurn * (c % 2 == 1 ? 1.0 : -1.0);
      heading = Eigen::Vector2d(std::cos(angle) * dir.x() - std::sin(angle) * dir.y(),
                                std::sin(angle) * dir.x() + std::cos(angle) * dir.y());
      if (!sensed_block(sim, heading, remaining, settings.block_distance)) chosen = c;
    }
    if (chosen < 0) {
      out.end = LegEnd::kBlocked;
      return out;
    }
    // A velocity that covers the rest exactly when it is shorter than one step at full speed.
    const Eigen::Vector2d command = heading * (std::min(speed, remaining) / step_time);
    const StepResult r = sim.step(command, rng);
    ++out.steps;
    out.travelled += r.travelled;
    if (trace != nullptr) trace->push_back(sim.state().position);
    if (r.blocked) {
      if (candidates == 1) {
        out.end = LegEnd::kBlocked;
        return out;
      }
      if ((sim.state().position - refused_at).squaredNorm() > arrive * arrive) refused = 0;
      refused |= 1U << chosen;
      refused_at = sim.state().position;
    }
    if (chosen != 0) {
      side = angle > 0.0 ? 1 : -1;
      detoured += r.travelled;
      if (detoured > settings.detour) {
        out.end = LegEnd::kBlocked;
        return out;
      }
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

LegResult drive_back(Simulator& sim, std::span<const Eigen::Vector2d> path, double speed, core::Rng& rng,
                     const core::StopCondition* stop, std::vector<Eigen::Vector2d>* trace) {
  const StraightLegSettings back{0.0, 20, 3.0, 0.0};  // touch only: the way was free a moment ago
  LegResult out;
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    const LegResult r = drive_straight(sim, *it, speed, back, rng, stop, trace);
    out.travelled += r.travelled;
    out.steps += r.steps;
    if (r.end != LegEnd::kArrived) {
      out.end = r.end;
      return out;
    }
  }
  return out;
}

}  // namespace amp::nav
