#pragma once
#include <memory>

#include "amp/core/settings_schema.hpp"
#include "amp/nav/execution.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/simulator.hpp"
#include "amp/nav/unicycle_disc.hpp"

namespace amp::nav {

class GridNavWorld;

// What `policy-search` and `dwa` share: the unicycle's limits (the disc is the task's robot), the
// motion noise G, the value function's obstacle cost, and a run's limits. Velocity and acceleration
// limits default to Nav2's DWB reference configuration (UnicycleDiscSettings).
struct DriveSettings {
  double v_max = 0.26;             // m/s
  double omega_max = 1.0;          // rad/s
  double accel = 2.5;              // m/s^2
  double alpha = 3.2;              // rad/s^2
  double sigma_v = 0.05;           // G: relative spread of the executed speed
  double sigma_omega = 0.05;       // G: rad/s spread of the executed turn rate
  double inflation = 0.5;          // m beyond the footprint where the value function charges obstacle cost
  double cost_scaling_factor = 10.0;  // 1/m
  double penalty = 2.0;            // extra cost per length at the footprint
  double goal_tolerance = 0.1;     // m
  double time_step = 0.1;          // s, the simulator's and the controllers' period
  double max_time = 300.0;         // s of simulated driving before a run gives up
  // m along the heading: 0 drives the problem's disc; else the footprint is a rectangle this long
  // and as wide as the disc (a robot and its margin, as Nav2's `footprint` beside `robot_radius`).
  double footprint_length = 0.0;
  static const core::SettingsSchema<DriveSettings>& schema();
  void validate() const { schema().validate(*this); }

  // Throw ParameterError naming footprint_length when it is neither 0 nor at least 2 radius.
  UnicycleDiscSettings robot(double radius) const;
  Footprint footprint(double radius) const;
  MotionNoise noise() const { return {sigma_v, sigma_omega}; }
};

// The task's base world as a map; throws ParameterError naming `method` when it is not one.
const GridNavWorld& map_world(const NavTask& task, const char* method);
// A simulator of the task's disc as a unicycle at its start, facing its goal, at rest.
Simulator unicycle_simulator(const NavTask& task, const DriveSettings& settings);

}  // namespace amp::nav
