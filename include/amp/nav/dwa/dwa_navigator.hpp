#pragma once
#include "amp/core/settings_schema.hpp"
#include "amp/nav/drive_settings.hpp"
#include "amp/nav/dwa/dynamic_window.hpp"
#include "amp/nav/navigator.hpp"

namespace amp::nav {

// `dwa` as a navigation method, the baseline of the policy-search paper: one run computes the value
// function (world::GridCostToGo on the task's map from its goal, the same obstacle cost as
// policy-search's) and drives the Dynamic Window Approach along its descent on the noisy unicycle.
// Record as policy-search's (record_execution, execution.hpp), without waypoints and value.
class DwaNavigator final : public Navigator {
 public:
  DwaNavigator(DriveSettings drive, DynamicWindowSettings dwa) : drive_(drive), dwa_(dwa) {}
  NavigationOutcome run(const NavTask& task, const core::StopCondition& stop, core::Rng& rng) override;
  static const core::SettingsSchema<DynamicWindowSettings>& schema();

 private:
  DriveSettings drive_;
  DynamicWindowSettings dwa_;
};

}  // namespace amp::nav
