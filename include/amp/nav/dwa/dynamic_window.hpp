#pragma once
#include <memory>

#include <Eigen/Core>

#include "amp/core/stop_condition.hpp"

#include "amp/nav/motion_controller.hpp"
#include "amp/nav/unicycle_disc.hpp"
#include "amp/world/grid_cost_to_go.hpp"

namespace amp::nav {

class NavWorld;

// Parameters of the Dynamic Window Approach. Sampling and horizon from Nav2's DWB reference
// configuration (nav2_params.yaml: sim_time 1.7 s, vx_samples 20, vtheta_samples 20,
// linear_granularity 0.05 m); the objective is Fox, Burgard & Thrun's (1997), with our weights.
struct DynamicWindowSettings {
  double sim_time = 1.7;            // s, the horizon each (v, omega) is simulated over
  int v_samples = 20;
  int omega_samples = 20;
  double granularity = 0.05;        // m between the checked points of a trajectory
  double heading_weight = 2.0;      // alpha
  double clearance_weight = 0.2;    // beta
  double velocity_weight = 0.2;     // gamma
  double clearance_cap = 1.0;       // m: more clearance scores as this
  double goal_tolerance = 0.1;      // m
  // Throws ParameterError naming the setting.
  void validate() const;
};

// The Dynamic Window Approach (Fox, Burgard & Thrun, "The dynamic window approach to collision
// avoidance", IEEE RAM 1997) following a value function, the prior planner of the policy-search
// paper. Each control period: the window of (v, omega) reachable within one period at the
// acceleration limits, within the velocity limits, sampled v_samples x omega_samples; each sample's
// circular arc simulated over sim_time; a sample is admissible when its arc keeps the disc free
// (then it can also brake in time: the arc's length covers the braking distance of every speed the
// limits allow in the horizon). The objective alpha heading + beta clearance + gamma velocity, each
// term in [0, 1] by its own scale: heading = 1 - |angle|/pi between the arc's final heading and the
// value function's descent direction at the arc's end; clearance = the arc's least clearance,
// capped and divided by the cap; velocity = v / v_max. (Min-max normalisation over the samples
// would blow sub-millimetre clearance differences in a door up into a whole term.) With no
// admissible sample the robot turns on the spot toward the descent. `cost_to_go` is computed from
// the goal (GridCostToGo::compute) and outlives this.
class DynamicWindow final : public MotionController {
 public:
  // Throws ParameterError for bad settings.
  DynamicWindow(const world::GridCostToGo& cost_to_go, Eigen::Vector2d origin, Eigen::Vector2d goal,
                UnicycleDiscSettings robot, DynamicWindowSettings settings = {});

  Eigen::Vector2d command(const Simulator& sim) override;
  bool arrived(const RobotState& s) const override;
  // Polled between rows of the window: one command scores v_samples x omega_samples arcs (seconds,
  // with a large window and footprint), so a run's time limit is kept inside a step. Once it fired,
  // command() chooses among the arcs scored so far.
  void set_stop(const core::StopCondition* stop) { stop_ = stop; }

 private:
  // The value function's descent direction at p: minus its gradient (central differences of the
  // cost-to-go over the cells beside p's); toward the goal in its cell or off the field.
  Eigen::Vector2d descent(const Eigen::Vector2d& p) const;

  const world::GridCostToGo* cost_;
  Eigen::Vector2d origin_, goal_;
  UnicycleDiscSettings robot_;
  DynamicWindowSettings settings_;
  const core::StopCondition* stop_ = nullptr;
};

}  // namespace amp::nav
