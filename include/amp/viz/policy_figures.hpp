#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amp/viz/footprint_outline.hpp"
#include "amp/world/problem.hpp"

namespace amp::viz {

// The pictures of "Policy search seeded by a value function" (Figures 3 and 4). Like the PGCS
// figures they take plain values, so viz stays below nav; the app converts.

// One phase of the paper's Figure 3: the value function's path, or the waypoints after a step.
struct PolicyPhase {
  std::string name;                     // the panel's caption, e.g. "(b) projected waypoints"
  std::vector<Eigen::Vector2d> points;  // in order from the start to the goal
  bool waypoints = true;                // draw each point as a waypoint (not for the cell path)
  std::optional<double> value;          // the policy's value V, shown in the caption
};

struct PolicyPhasesDrawing {
  std::vector<PolicyPhase> phases;
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), goal = Eigen::Vector2d::Zero();
  FootprintOutline footprint;  // the robot, drawn at the start, the goal and (a rectangle) each waypoint
  std::vector<Eigen::Vector2d> trace;  // one run's driven positions, on the last panel; empty: none
  bool arrived = true;                 // false: the trace ends where the run stopped, marked with a cross
};

// Figure 3: one panel per phase, two per row, each the map with the phase's path (waypoints as
// dots) and the footprint at the start facing the goal (as the robot starts) and at the goal facing
// along the path's last segment; a rectangle is also outlined at each waypoint, facing along the
// segment it begins (how it crosses doors). The trace, if any, is drawn on the last panel. Captions
// too long for a panel wrap onto two lines. Only the world's 2-D outline is drawn.
std::string policy_phases_svg(const world::Problem& problem, const PolicyPhasesDrawing& drawing,
                              const std::string& title);

// One method's velocity profile: its speed at each time step.
struct VelocityProfile {
  std::string label;
  std::vector<double> speeds;  // m/s, one per step
};

// Figure 4: speed against time, one line per profile on shared axes, steps of `time_step` s.
// Throws ParameterError for time_step <= 0.
std::string velocity_profiles_svg(const std::vector<VelocityProfile>& profiles, double time_step,
                                  const std::string& title);

}  // namespace amp::viz
