#pragma once
#include "amp/core/settings_schema.hpp"
#include "amp/nav/drive_settings.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/nav/policy/policy_planner.hpp"
#include "amp/nav/policy/waypoint_controller.hpp"

namespace amp::nav {

// The parameters of `policy-search` beyond DriveSettings: the controller's and the reward's.
struct PolicyNavigatorSettings {
  // A footprint that is not a disc switches within this of a waypoint (or once past it), and turns
  // on the spot above this heading error: about one control period's travel at top speed, and a
  // heading error that leaves a 54 cm body in a 60 cm door.
  static constexpr double kRectangleSwitch = 0.03;       // m
  static constexpr double kRectangleTurnInPlace = 0.2;   // rad
  double d_approach = 0.3;     // m (eq. 3)
  double heading_gain = 2.5;   // 1/s
  double c = 1.0, c_time = 1.0, g = 100.0, h = 50.0;  // the reward (PolicyRewardSettings)
  double safety = 0.05, safety_per_speed = 0.25, sigma = 0.03;
  int max_insertions = 30;
  static const core::SettingsSchema<PolicyNavigatorSettings>& schema();
  void validate() const { schema().validate(*this); }
  PolicyPlannerSettings planner(const DriveSettings& drive) const;
  // d_approach is at most goal_tolerance for a footprint that is not a disc (it turns in place).
  WaypointControllerSettings controller(const DriveSettings& drive) const;
};

// `policy-search` as a navigation method: one run plans (plan_policy on the task's map, from its
// start to its goal) and drives the policy once on the noisy unicycle (execute), the noise from the
// run's seed. Record: status solved when it arrived, path_length the distance driven, nodes the
// waypoints; extra: arrived, execution_time_s (simulated), distance, min_clearance, collisions,
// waypoints, value (the policy's V). The planning time is the outcome's, not the record's (the
// record depends on the seed alone).
class PolicyNavigator final : public Navigator {
 public:
  PolicyNavigator(DriveSettings drive, PolicyNavigatorSettings policy) : drive_(drive), policy_(policy) {}
  NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) override;

 private:
  DriveSettings drive_;
  PolicyNavigatorSettings policy_;
};

}  // namespace amp::nav
