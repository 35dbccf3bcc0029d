#include "amp/nav/drive_settings.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"

namespace amp::nav {

const core::SettingsSchema<DriveSettings>& DriveSettings::schema() {
  using S = DriveSettings;
  static const core::SettingsSchema<S> schema(
      "drive",
      {core::real_field<S>("v_max", &S::v_max, 1e-6, 100, "m/s, top speed"),
       core::real_field<S>("omega_max", &S::omega_max, 1e-6, 100, "rad/s, top turn rate"),
       core::real_field<S>("accel", &S::accel, 1e-6, 1000, "m/s^2, acceleration limit"),
       core::real_field<S>("alpha", &S::alpha, 1e-6, 1000, "rad/s^2, angular acceleration limit"),
       core::real_field<S>("sigma_v", &S::sigma_v, 0, 10, "motion noise G: relative spread of the speed"),
       core::real_field<S>("sigma_omega", &S::sigma_omega, 0, 100, "motion noise G: rad/s spread of the turn rate"),
       core::real_field<S>("inflation", &S::inflation, 0, 1e6, "m beyond the footprint where the value function charges obstacle cost"),
       core::real_field<S>("cost_scaling_factor", &S::cost_scaling_factor, 0, 1e6, "1/m, decay of the obstacle cost"),
       core::real_field<S>("penalty", &S::penalty, 0, 1e4, "extra cost per length at the footprint"),
       core::real_field<S>("goal_tolerance", &S::goal_tolerance, 1e-6, 1e6, "m, arrived within this of the goal"),
       core::real_field<S>("time_step", &S::time_step, 1e-4, 10, "s, simulator and control period"),
       core::real_field<S>("max_time", &S::max_time, 1e-3, 1e7, "s of simulated driving before a run gives up"),
       core::real_field<S>("footprint_length", &S::footprint_length, 0, 100,
                           "m: 0 drives the problem's disc; else a rectangle this long, as wide as the disc, checked at its heading")});
  return schema;
}

UnicycleDiscSettings DriveSettings::robot(double radius) const {
  if (footprint_length != 0.0 && footprint_length < 2.0 * radius) {
    throw ParameterError("footprint_length must be 0 (the problem's disc) or at least the robot's width " +
                         std::to_string(2.0 * radius) + " m, got " + std::to_string(footprint_length));
  }
  return {radius, 0.0, v_max, omega_max, accel, alpha, footprint_length};
}

Footprint DriveSettings::footprint(double radius) const { return UnicycleDisc(robot(radius)).footprint(); }

const GridNavWorld& map_world(const NavTask& task, const char* method) {
  const GridNavWorld* grid = task.timeline->base()->as_map();
  if (grid == nullptr) {
    throw ParameterError(std::string(method) + " plans on map worlds (map_server or MovingAI); problem '" + task.name +
                         "' is not one");
  }
  return *grid;
}

Simulator unicycle_simulator(const NavTask& task, const DriveSettings& settings) {
  RobotState start;
  start.position = task.start;
  const Eigen::Vector2d to = task.goal - task.start;
  start.heading = to.squaredNorm() > 0.0 ? std::atan2(to.y(), to.x()) : 0.0;
  SimulatorSettings sim;
  sim.time_step = settings.time_step;
  sim.contact_tolerance = std::min(1e-6, 1e-3 * task.robot_radius);
  return Simulator(task.timeline, std::make_shared<const UnicycleDisc>(settings.robot(task.robot_radius)), start, sim);
}

}  // namespace amp::nav
