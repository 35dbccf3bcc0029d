#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/robot_model.hpp"

namespace amp::core {
class Rng;
}

namespace amp::nav {

class NavWorld;

struct RangeSensorSettings {
  int count = 8;
  double max_range = 0.1;       // m beyond the rim: Khepera's infrared sensors see a few centimetres
  double noise_stddev = 0.002;  // m; 0 for exact readings (no random draw then)
  double first_angle = 0.0;     // rad, of sensor 0 from the robot's heading
  // Throws ParameterError unless count >= 1, max_range > 0 and noise_stddev >= 0 (all finite).
  void validate() const;
};

// N range sensors evenly spaced around a disc robot, measuring from the disc's rim outwards along
// rays through its centre, up to a maximum range, with additive Gaussian noise (clipped to
// [0, max_range]). Default: Khepera-like, 8 sensors seeing a few centimetres.
class RangeSensorRing {
 public:
  explicit RangeSensorRing(RangeSensorSettings settings = {});

  const RangeSensorSettings& settings() const { return settings_; }
  int count() const { return settings_.count; }
  // Direction of sensor i for a robot heading `heading` (unit vector).
  Eigen::Vector2d direction(int i, double heading) const;
  // One reading per sensor into `out` (size count()); noise draws come from `rng` in sensor order.
  void read(const NavWorld& world, const RobotState& s, double radius, core::Rng& rng, std::span<double> out) const;

 private:
  RangeSensorSettings settings_;
  std::vector<double> angles_;  // of each sensor from the heading
};

}  // namespace amp::nav
