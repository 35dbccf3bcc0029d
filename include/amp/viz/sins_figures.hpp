#pragma once
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amp/world/shapes2d.hpp"

namespace amp::viz {

// The pictures of SINS (Ram & Santamaria 1993, Figures 4 and 5). Like the PGCS and policy-search
// figures they take plain values, so viz stays below nav; the app converts.

// The six estimators' cumulative averages after one world (nav::Estimators, in the paper's order).
struct SinsCurvePoint {
  double solved_fraction = 0.0;
  double steps = 0.0;
  double distance = 0.0;
  double distance_ratio = 0.0;  // actual / optimal over the solved worlds (0 when none is)
  double virtual_collisions = 0.0;
  double time_ms = 0.0;  // per world
};

// One system's curves: point k is the average over worlds 1..k+1.
struct SinsCurves {
  std::string system;  // the legend's label ("static", "random", "adaptive")
  std::vector<SinsCurvePoint> points;
};

// Figure 5: six small panels (solved fraction, steps, distance, actual / optimal distance, virtual
// collisions, time per world), each the cumulative average against world number, one line per
// system, with a shared legend.
std::string sins_learning_svg(const std::vector<SinsCurves>& systems, const std::string& title);

// One world as driven (Figure 4).
struct SinsRunDrawing {
  double width = 40.0, height = 40.0;  // the box [0, width] x [0, height]
  std::vector<world::Circle> circles;
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), goal = Eigen::Vector2d::Zero();
  double robot_radius = 0.25;
  double goal_tolerance = 0.5;
  std::vector<Eigen::Vector2d> positions;  // after every step, the start first
  // The parameters in force during each step, each normalised to [0, 1] over its range.
  std::vector<std::array<double, 4>> parameters;
  std::array<std::string, 4> parameter_names;  // legend labels, e.g. "obstacle gain [0, 5]"
  bool solved = false;
};

// Figure 4: the world (box, circles, start, goal) with the driven path over it, and above it a strip
// with the four schema parameters against the step number, each on its range.
std::string sins_run_svg(const SinsRunDrawing& drawing, const std::string& title);

}  // namespace amp::viz
