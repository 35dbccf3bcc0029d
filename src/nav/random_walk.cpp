#include "amp/nav/random_walk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

RandomWalk::RandomWalk(RandomWalkSettings settings, std::function<double(const Eigen::Vector2d&)> visited)
    : settings_(settings), visited_(std::move(visited)) {
  if (!(settings_.speed > 0.0) || !std::isfinite(settings_.speed)) throw ParameterError("walk speed must be > 0");
  if (!(settings_.turn_every > 0.0)) throw ParameterError("turn_every must be > 0");
  if (!(settings_.avoid_distance >= 0.0) || !(settings_.lookahead >= 0.0)) {
    throw ParameterError("avoid_distance and lookahead must be >= 0");
  }
}

void RandomWalk::turn(const Simulator& sim, core::Rng& rng, bool novelty) {
  const RangeSensorRing& ring = sim.sensors();
  const auto ranges = sim.ranges();
  clear_.clear();
  for (int i = 0; i < ring.count(); ++i) {
    if (ranges[static_cast<std::size_t>(i)] >= settings_.avoid_distance) clear_.push_back(i);
  }
  const double spread = std::numbers::pi / ring.count();  // half the spacing of the sensors
  const double heading = sim.state().heading;
  if (clear_.empty()) {
    heading_ = rng.uniform(-std::numbers::pi, std::numbers::pi);
    return;
  }
  const std::size_t first = rng.uniform_index(clear_.size());
  int pick = clear_[first];
  if (novelty && settings_.lookahead > 0.0 && visited_) {
    // From a random first candidate, so that ties (equally unvisited ends) fall at random.
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < clear_.size(); ++j) {
      const int i = clear_[(first + j) % clear_.size()];
      // As far as the way is open along that direction (a range finder's reach), so that the walk
      // is drawn to open space it can get to, not to the unvisited far side of a wall.
      const Eigen::Vector2d d = ring.direction(i, heading);
      const double open = sim.next_world().ray_cast(sim.state().position, d, settings_.lookahead);
      const Eigen::Vector2d p = sim.state().position + std::max(0.0, open - sim.robot().radius()) * d;
      const double v = visited_(p);
      if (v < least) least = v, pick = i;
    }
  }
  const Eigen::Vector2d d = ring.direction(pick, heading);
  heading_ = std::atan2(d.y(), d.x()) + rng.uniform(-spread, spread);
}

Eigen::Vector2d RandomWalk::command(const Simulator& sim, bool blocked, core::Rng& rng) {
  const Eigen::Vector2d ahead(std::cos(heading_), std::sin(heading_));
  bool obstacle_ahead = false;
  const RangeSensorRing& ring = sim.sensors();
  const auto ranges = sim.ranges();
  for (int i = 0; i < ring.count(); ++i) {
    // Sensors within 45 degrees of the heading look ahead.
    if (ranges[static_cast<std::size_t>(i)] < settings_.avoid_distance &&
        ring.direction(i, sim.state().heading).dot(ahead) > std::numbers::sqrt2 / 2) {
      obstacle_ahead = true;
    }
  }
  if (!started_ || blocked || obstacle_ahead || rng.uniform01() * settings_.turn_every < 1.0) {
    started_ = true;
    // After a blocked move the novelty walk turns at random too: its best direction may be the one
    // that just failed (a sensor between two rays reads clear), and it would push there forever.
    turn(sim, rng, !blocked);
  }
  return settings_.speed / sim.time_step() * Eigen::Vector2d(std::cos(heading_), std::sin(heading_));
}

}  // namespace amp::nav
