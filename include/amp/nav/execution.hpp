#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace amp::core {
class Rng;
class StopCondition;
struct RunRecord;
}  // namespace amp::core

namespace amp::nav {

class MotionController;
struct NavigationOutcome;
class Simulator;

// Gaussian noise G on the commands a controller sends (the policy-search paper's motion noise about
// the expected trajectory): v times 1 + N(0, sigma_v), omega plus N(0, sigma_omega).
struct MotionNoise {
  double sigma_v = 0.05;      // relative
  double sigma_omega = 0.05;  // rad/s
  // Throws ParameterError ("a noise with negative spread") for a negative or non-finite spread.
  void validate() const;
};

// What one run of a controller on the noisy robot did (the paper's Table 2 and Figure 4).
struct Execution {
  bool arrived = false;          // the controller says so and the robot is where it says
  double time_s = 0.0;           // simulated
  double distance = 0.0;         // travelled
  double min_clearance = 0.0;    // of the robot's footprint, over the run
  std::size_t collisions = 0;    // moves the simulator cut short: footprint contacts
  std::vector<Eigen::Vector2d> trace;  // positions, one per step
  std::vector<double> speeds;          // distance per step / time step (the velocity profile)
};

// Runs `controller` on the simulator's robot until it arrives, `time_limit_s` of simulated time pass
// or `stop` fires. Each step the command gets noise from `rng`; the simulator never moves the robot
// through an obstacle (a refused move counts as a collision).
Execution execute(Simulator& sim, MotionController& controller, const MotionNoise& noise, double time_limit_s,
                  core::Rng& rng, const core::StopCondition* stop = nullptr);

// The execution of a run into its outcome: the typed DriveSummary, and the flat metrics (arrived,
// execution_time_s, distance, min_clearance, collisions) into the record's status, path_length and
// extra. `stopped`: the run's stop fired, so a robot that did not arrive timed out rather than
// failed. Shared by policy-search and dwa.
void record_execution(const Execution& e, bool stopped, NavigationOutcome& out);

}  // namespace amp::nav
