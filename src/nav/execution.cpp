#include "amp/nav/execution.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/run_record.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/nav/motion_controller.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

void MotionNoise::validate() const {
  if (!(sigma_v >= 0.0) || !std::isfinite(sigma_v) || !(sigma_omega >= 0.0) || !std::isfinite(sigma_omega)) {
    throw ParameterError("a noise with negative spread: sigma_v " + std::to_string(sigma_v) + ", sigma_omega " +
                         std::to_string(sigma_omega));
  }
}

Execution execute(Simulator& sim, MotionController& controller, const MotionNoise& noise, double time_limit_s,
                  core::Rng& rng, const core::StopCondition* stop) {
  noise.validate();
  Execution out;
  const std::size_t blocked0 = sim.blocked_moves();
  const double t0 = sim.time();
  out.trace.push_back(sim.state().position);
  const Footprint& f = sim.footprint();
  out.min_clearance = f.clearance(sim.next_world(), sim.state().position, sim.state().heading);
  while (!controller.arrived(sim.state()) && sim.time() - t0 < time_limit_s) {
    // Every step: one DWA step scores v_samples x omega_samples arcs, so a coarser poll overran the
    // time limit several-fold (the property tests found 0.8 s runs under a 0.2 s limit).
    if (stop != nullptr && stop->time_up()) break;
    Eigen::Vector2d cmd = controller.command(sim);
    cmd.x() *= 1.0 + noise.sigma_v * rng.normal();
    cmd.y() += noise.sigma_omega * rng.normal();
    const StepResult step = sim.step(cmd, rng);
    out.distance += step.travelled;
    out.trace.push_back(sim.state().position);
    out.speeds.push_back(step.travelled / sim.time_step());
    out.min_clearance = std::min(out.min_clearance, f.clearance(sim.world(), sim.state().position, sim.state().heading));
  }
  out.arrived = controller.arrived(sim.state());
  out.time_s = sim.time() - t0;
  out.collisions = sim.blocked_moves() - blocked0;
  return out;
}

void record_execution(const Execution& e, bool stopped, NavigationOutcome& out) {
  out.drive = DriveSummary{e.arrived, e.time_s, e.distance, e.min_clearance, e.collisions, std::nullopt};
  core::RunRecord& r = out.record;
  r.status = e.arrived ? core::PlanStatus::kSolved : stopped ? core::PlanStatus::kTimeout : core::PlanStatus::kUnsolvable;
  r.path_length = e.distance;
  r.extra["arrived"] = e.arrived ? 1.0 : 0.0;
  r.extra["execution_time_s"] = e.time_s;
  r.extra["distance"] = e.distance;
  r.extra["min_clearance"] = e.min_clearance;
  r.extra["collisions"] = static_cast<double>(e.collisions);
}

}  // namespace amp::nav
