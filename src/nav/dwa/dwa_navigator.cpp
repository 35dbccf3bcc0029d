#include "amp/nav/dwa/dwa_navigator.hpp"

#include <chrono>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/world/inflation_cost.hpp"

namespace amp::nav {

const core::SettingsSchema<DynamicWindowSettings>& DwaNavigator::schema() {
  using S = DynamicWindowSettings;
  static const core::SettingsSchema<S> schema(
      "dwa", {core::real_field<S>("sim_time", &S::sim_time, 1e-3, 100, "s, horizon of each simulated arc (DWB)"),
              core::integer_field<S>("v_samples", &S::v_samples, 1, 1000, "speeds sampled in the window (DWB vx_samples)"),
              core::integer_field<S>("omega_samples", &S::omega_samples, 1, 1000, "turn rates sampled (DWB vtheta_samples)"),
              core::real_field<S>("granularity", &S::granularity, 1e-4, 10, "m between checked points of an arc"),
              core::real_field<S>("heading_weight", &S::heading_weight, 0, 1e6, "alpha (Fox et al.)"),
              core::real_field<S>("clearance_weight", &S::clearance_weight, 0, 1e6, "beta"),
              core::real_field<S>("velocity_weight", &S::velocity_weight, 0, 1e6, "gamma"),
              core::real_field<S>("clearance_cap", &S::clearance_cap, 1e-6, 1e6, "m, more clearance scores as this")});
  return schema;
}

NavigationOutcome DwaNavigator::run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) {
  drive_.validate();
  const GridNavWorld& world = map_world(task, "dwa");
  NavigationOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  world::InflationSettings inflation;
  inflation.inscribed_radius = task.robot_radius;
  inflation.inflation_radius = task.robot_radius + drive_.inflation;
  inflation.cost_scaling_factor = drive_.cost_scaling_factor;
  inflation.penalty = drive_.penalty;
  world::GridCostToGo cost(world::inflate(world.obstacles(), inflation));
  const Eigen::Vector2i goal = world.grid().world_to_cell(task.goal);
  const Eigen::Vector2i start = world.grid().world_to_cell(task.start);
  cost.compute(cost.index(goal.x(), goal.y()));
  if (!cost.free(start.x(), start.y()) || cost.distance(cost.index(start.x(), start.y())) == world::GridCostToGo::kUnreachable) {
    throw ParameterError("dwa: the goal is not reachable from the start for the robot's footprint");
  }
  DynamicWindowSettings dwa = dwa_;
  dwa.goal_tolerance = drive_.goal_tolerance;
  DynamicWindow controller(cost, world.grid().origin(), task.goal, drive_.robot(task.robot_radius), dwa);
  controller.set_stop(&stop);
  out.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Simulator sim = unicycle_simulator(task, drive_);
  const Execution e = execute(sim, controller, drive_.noise(), drive_.max_time, rng, &stop);
  record_execution(e, stop.fired(), out);
  out.trace = e.trace;
  out.speeds = e.speeds;
  return out;
}

void register_dwa(NavigatorRegistry& registry) {
  std::vector<core::ParamSpec> specs = DwaNavigator::schema().specs();
  for (const core::ParamSpec& s : DriveSettings::schema().specs()) specs.push_back(s);
  registry.add({"dwa",
                "the Dynamic Window Approach (Fox, Burgard & Thrun 1997) following the grid value function, on a noisy "
                "unicycle (the policy-search paper's baseline)",
                specs},
               [](const core::Params& p) -> std::unique_ptr<Navigator> {
                 return std::make_unique<DwaNavigator>(DriveSettings::schema().read(p), DwaNavigator::schema().read(p));
               });
}

}  // namespace amp::nav
