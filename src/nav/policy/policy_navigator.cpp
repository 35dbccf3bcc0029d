#include "amp/nav/policy/policy_navigator.hpp"

#include <algorithm>
#include <chrono>

#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/navigator_catalog.hpp"

namespace amp::nav {

const core::SettingsSchema<PolicyNavigatorSettings>& PolicyNavigatorSettings::schema() {
  using S = PolicyNavigatorSettings;
  static const core::SettingsSchema<S> schema(
      "policy-search",
      {core::real_field<S>("d_approach", &S::d_approach, 1e-6, 1e6, "m: switch to the next waypoint within this (eq. 3)"),
       core::real_field<S>("heading_gain", &S::heading_gain, 1e-6, 1e6, "1/s, turn rate per radian of heading error"),
       core::real_field<S>("c", &S::c, 0, 1e9, "reward: cost per metre"),
       core::real_field<S>("c_time", &S::c_time, 0, 1e9, "reward: cost per second"),
       core::real_field<S>("g", &S::g, 0, 1e9, "reward: reaching the goal"),
       core::real_field<S>("h", &S::h, 0, 1e9, "reward: cost per metre inside the safety range"),
       core::real_field<S>("safety", &S::safety, 0, 1e6, "m, safety range at rest beyond the footprint"),
       core::real_field<S>("safety_per_speed", &S::safety_per_speed, 0, 1e6, "s, safety range growth per m/s"),
       core::real_field<S>("sigma", &S::sigma, 0, 1e6, "m, G's spread across the path when planning"),
       core::integer_field<S>("max_insertions", &S::max_insertions, 0, 1e6, "waypoints inserted at most (eq. 10)")});
  return schema;
}

PolicyPlannerSettings PolicyNavigatorSettings::planner(const DriveSettings& drive) const {
  PolicyPlannerSettings p;
  p.inflation = drive.inflation;
  p.cost_scaling_factor = drive.cost_scaling_factor;
  p.penalty = drive.penalty;
  p.reward.c = c;
  p.reward.c_time = c_time;
  p.reward.g = g;
  p.reward.h = h;
  p.reward.safety = safety;
  p.reward.safety_per_speed = safety_per_speed;
  p.reward.sigma = sigma;
  p.search.max_insertions = max_insertions;
  p.search.v_max = drive.v_max;
  p.search.v_min = std::min(p.search.v_min, drive.v_max);
  return p;
}

WaypointControllerSettings PolicyNavigatorSettings::controller(const DriveSettings& drive) const {
  WaypointControllerSettings c{d_approach, heading_gain, drive.goal_tolerance, drive.accel};
  if (drive.footprint_length > 0.0) {
    // A footprint that is not a disc was certified turning in place at the waypoints: it is driven
    // so, stopping at each turn and switching there (not d_approach before, which swung its body
    // into the lab's door frame: 5 of 10 runs arrived with d_approach 0.3, 10 of 10 with 0.1).
    c.d_approach = std::min(d_approach, kRectangleSwitch);
    c.lookahead = d_approach;
    c.turn_in_place = kRectangleTurnInPlace;
  }
  return c;
}

NavigationOutcome PolicyNavigator::run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) {
  drive_.validate();
  policy_.validate();
  const GridNavWorld& world = map_world(task, "policy-search");
  NavigationOutcome out;
  const auto t0 = std::chrono::steady_clock::now();
  const PolicyPlan plan = plan_policy(world, task.start, task.goal, drive_.footprint(task.robot_radius), policy_.planner(drive_), &stop);
  out.planning_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Simulator sim = unicycle_simulator(task, drive_);
  // A plan cut short by the stop is not driven: the run has no time left (the robot stays at its start).
  Execution e;
  if (!plan.stopped) {
    WaypointController controller(plan.search.final, policy_.controller(drive_));
    e = execute(sim, controller, drive_.noise(), drive_.max_time, rng, &stop);
  } else {
    e.trace = {sim.state().position};
    e.min_clearance = sim.footprint().clearance(sim.next_world(), sim.state().position, sim.state().heading);
  }
  record_execution(e, stop.fired(), out);
  out.record.nodes = plan.search.final.size();
  out.drive->waypoints = plan.search.final.size();
  out.record.extra["waypoints"] = static_cast<double>(plan.search.final.size());
  out.record.extra["value"] = plan.search.value_final;
  out.trace = e.trace;
  out.speeds = e.speeds;
  const auto positions = [](const std::vector<State>& w) {
    std::vector<Eigen::Vector2d> p;
    for (const State& s : w) p.emplace_back(s[0], s[1]);
    return p;
  };
  out.stages = {{"(a) value iteration path", plan.dp_path, false, std::nullopt},
                {"(b) projected waypoints", positions(plan.search.projected), true, plan.search.value_projected},
                {"(c) after policy search", positions(plan.search.searched), true, plan.search.value_searched},
                {plan.squared_crossings > 0 ? "(d) after insertions, passages squared" : "(d) after insertions", positions(plan.search.final), true, plan.search.value_final}};
  return out;
}

void register_policy_search(NavigatorRegistry& registry) {
  std::vector<core::ParamSpec> specs = PolicyNavigatorSettings::schema().specs();
  for (const core::ParamSpec& s : DriveSettings::schema().specs()) specs.push_back(s);
  registry.add({"policy-search",
                "policy search seeded by a value function: grid value iteration, 5-D waypoints optimised by gradient "
                "ascent and insertion, driven on a noisy unicycle",
                specs},
               [](const core::Params& p) -> std::unique_ptr<Navigator> {
                 return std::make_unique<PolicyNavigator>(DriveSettings::schema().read(p),
                                                          PolicyNavigatorSettings::schema().read(p));
               });
}

}  // namespace amp::nav
