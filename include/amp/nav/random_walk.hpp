#pragma once
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace amp::core {
class Rng;
}

namespace amp::nav {

class Simulator;

struct RandomWalkSettings {
  double speed = 0.01;           // distance per time step
  double turn_every = 50.0;      // mean steps between spontaneous heading changes (geometric)
  double avoid_distance = 0.01;  // a sensor reading ahead below this makes the walk turn away
  // > 0: the novelty walk. At each turn it heads for the clear sensor direction whose open end (as
  // far as a range finder sees along it, up to this distance) is least visited (lowest `visited`
  // density), instead of a random clear one. It assumes a range finder of this reach (a laser).
  double lookahead = 0.0;
};

// The exploration of Vlassis et al. (a random walk), and the better strategy their section 6 asks
// for as an option (a novelty walk). The walk keeps a heading and turns when a sensor ahead reads
// an obstacle, when the last move was blocked, or at random (mean turn_every steps). A turn picks
// one of the sensor directions that read clear (uniformly, or the least visited one, but after a
// blocked move always at random) and a random offset within half the sensor spacing. Commands are
// holonomic velocities.
class RandomWalk {
 public:
  // `visited(p)`: a density of past positions at p, used by the novelty walk (may be empty then
  // the walk is random). Throws ParameterError for non-positive speed or turn_every, or negative
  // distances.
  RandomWalk(RandomWalkSettings settings, std::function<double(const Eigen::Vector2d&)> visited = {});

  // The velocity command for the next step; `blocked`: the last step was cut short.
  Eigen::Vector2d command(const Simulator& sim, bool blocked, core::Rng& rng);
  double heading() const { return heading_; }

 private:
  void turn(const Simulator& sim, core::Rng& rng, bool novelty);

  RandomWalkSettings settings_;
  std::function<double(const Eigen::Vector2d&)> visited_;
  double heading_ = 0.0;
  bool started_ = false;
  std::vector<int> clear_;  // scratch
};

}  // namespace amp::nav
