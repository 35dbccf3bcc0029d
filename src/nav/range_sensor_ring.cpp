#include "amp/nav/range_sensor_ring.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/nav_world.hpp"

namespace amp::nav {

void RangeSensorSettings::validate() const {
  if (count < 1) throw ParameterError("range sensors: count must be >= 1, got " + std::to_string(count));
  if (!(max_range > 0.0) || !std::isfinite(max_range)) {
    throw ParameterError("range sensors: max_range must be > 0, got " + std::to_string(max_range));
  }
  if (!(noise_stddev >= 0.0) || !std::isfinite(noise_stddev)) {
    throw ParameterError("range sensors: noise_stddev must be >= 0, got " + std::to_string(noise_stddev));
  }
  if (!std::isfinite(first_angle)) throw ParameterError("range sensors: first_angle must be finite");
}

RangeSensorRing::RangeSensorRing(RangeSensorSettings settings) : settings_(settings) {
  settings_.validate();
  for (int i = 0; i < settings_.count; ++i) {
    angles_.push_back(settings_.first_angle + 2.0 * std::numbers::pi * i / settings_.count);
  }
}

Eigen::Vector2d RangeSensorRing::direction(int i, double heading) const {
  const double a = heading + angles_[static_cast<std::size_t>(i)];
  return {std::cos(a), std::sin(a)};
}

void RangeSensorRing::read(const NavWorld& world, const RobotState& s, double radius, core::Rng& rng,
                           std::span<double> out) const {
  const double max_range = settings_.max_range;
  for (int i = 0; i < settings_.count; ++i) {
    // Cast from the centre: a rim point may itself touch the obstacle it should measure.
    const double hit = world.ray_cast(s.position, direction(i, s.heading), radius + max_range);
    double range = std::clamp(hit - radius, 0.0, max_range);
    if (settings_.noise_stddev > 0.0) range = std::clamp(range + rng.normal(0.0, settings_.noise_stddev), 0.0, max_range);
    out[static_cast<std::size_t>(i)] = range;
  }
}

}  // namespace amp::nav
