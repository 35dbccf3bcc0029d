#pragma once
#include <array>
#include <span>

#include <Eigen/Core>

namespace amp::nav {

// SINS's four perceived inputs (Ram & Santamaria 1993, Sec. 2.3), each in [0, 1], computed once per
// control interval from what the robot sensed and did during it. The paper names them only:
//  - Obstacle-Density, "a measure of the occupied areas that impede navigation": the mean over the
//    interval's steps and the sensors of 1 - d / S, d the reading clipped to the sphere of
//    influence S (0: nothing within S; 1: touching all round);
//  - Absolute-Motion, "the activity of the system": the distance driven / (max_speed x steps);
//  - Relative-Motion, "the change in motion activity": (Absolute-Motion now - before + 1) / 2;
//  - Motion-Towards-Goal, "how much progress the system has actually made towards the goal": the
//    decrease of the distance to the goal / (max_speed x steps), mapped from [-1, 1] as (m + 1) / 2.
class EnvironmentTrends {
 public:
  EnvironmentTrends(double sphere_of_influence, double max_speed);

  // A new world: the interval and the previous Absolute-Motion start afresh.
  void reset(const Eigen::Vector2d& position, const Eigen::Vector2d& goal);
  // One step: the readings taken there, then the position reached.
  void step(std::span<const double> readings, const Eigen::Vector2d& reached);
  // The interval's inputs {density, absolute, relative, towards goal}; starts the next interval.
  // An interval without steps gives {0, 0, 0.5, 0.5}.
  std::array<double, 4> close_interval();
  int steps() const { return steps_; }

 private:
  double sphere_, max_speed_;
  Eigen::Vector2d goal_ = Eigen::Vector2d::Zero(), position_ = Eigen::Vector2d::Zero(), start_ = Eigen::Vector2d::Zero();
  double density_sum_ = 0.0, driven_ = 0.0, previous_absolute_ = 0.0;
  int steps_ = 0;
};

}  // namespace amp::nav
