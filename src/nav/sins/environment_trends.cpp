#include "amp/nav/sins/environment_trends.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::nav {

EnvironmentTrends::EnvironmentTrends(double sphere_of_influence, double max_speed)
    : sphere_(sphere_of_influence), max_speed_(max_speed) {
  if (!(sphere_ > 0.0) || !std::isfinite(sphere_)) {
    throw ParameterError("sphere_of_influence must be > 0, got " + std::to_string(sphere_));
  }
  if (!(max_speed_ > 0.0) || !std::isfinite(max_speed_)) throw ParameterError("max_speed must be > 0, got " + std::to_string(max_speed_));
}

void EnvironmentTrends::reset(const Eigen::Vector2d& position, const Eigen::Vector2d& goal) {
  goal_ = goal;
  position_ = start_ = position;
  density_sum_ = driven_ = previous_absolute_ = 0.0;
  steps_ = 0;
}

void EnvironmentTrends::step(std::span<const double> readings, const Eigen::Vector2d& reached) {
  double density = 0.0;
  for (const double d : readings) density += 1.0 - std::clamp(d, 0.0, sphere_) / sphere_;
  density_sum_ += readings.empty() ? 0.0 : density / static_cast<double>(readings.size());
  driven_ += (reached - position_).norm();
  position_ = reached;
  ++steps_;
}

std::array<double, 4> EnvironmentTrends::close_interval() {
  std::array<double, 4> in{0.0, 0.0, 0.5, 0.5};
  if (steps_ > 0) {
    const double reach = max_speed_ * steps_;
    const double absolute = std::clamp(driven_ / reach, 0.0, 1.0);
    const double progress = std::clamp(((goal_ - start_).norm() - (goal_ - position_).norm()) / reach, -1.0, 1.0);
    in = {density_sum_ / steps_, absolute, 0.5 * (absolute - previous_absolute_ + 1.0), 0.5 * (progress + 1.0)};
    previous_absolute_ = absolute;
  }
  start_ = position_;
  density_sum_ = driven_ = 0.0;
  steps_ = 0;
  return in;
}

}  // namespace amp::nav
