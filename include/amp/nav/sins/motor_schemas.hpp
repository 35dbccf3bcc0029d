#pragma once
#include <array>
#include <span>

#include <Eigen/Core>

#include "amp/core/settings_schema.hpp"

namespace amp::core {
class Rng;
}

namespace amp::nav {

// The four schema parameters SINS tunes (Ram & Santamaria 1993, Sec. 2.2), and their ranges. The
// paper gives none; these follow AuRA's motor-schema practice (Arkin 1989): gains of the order of
// one (a goal gain of 1 moves the robot at full speed in free space), noise up to the goal's
// pull, held for one to twenty steps.
struct SchemaParameters {
  double obstacle_gain = 2.5;      // AVOID-STATIC-OBSTACLE's magnitude at the safety margin
  double goal_gain = 1.0;          // MOVE-TO-GOAL's magnitude
  double noise_gain = 0.5;         // NOISE's magnitude
  double noise_persistence = 10.5; // steps a noise direction is held (rounded, at least 1)

  struct Range {
    double lo, hi;
  };
  static constexpr Range kObstacleGain{0.0, 5.0};
  static constexpr Range kGoalGain{0.0, 2.0};
  static constexpr Range kNoiseGain{0.0, 1.0};
  static constexpr Range kNoisePersistence{1.0, 20.0};
  // The middle of every range: the static system's default.
  static SchemaParameters middle();
  // Throws ParameterError (one line naming the parameter and its range) outside the ranges.
  void validate() const;
  // Each parameter mapped to [0, 1] over its range (the case library's outputs), and back (clamped).
  std::array<double, 4> normalised() const;
  static SchemaParameters from_normalised(const std::array<double, 4>& u);
  // The four as method parameters (obstacle_gain, goal_gain, noise_gain, noise_persistence), with
  // the ranges above; their defaults are the middle of the ranges.
  static const core::SettingsSchema<SchemaParameters>& schema();
};

struct SchemaSettings {
  double sphere_of_influence = 2.0;  // m beyond the rim: obstacles farther away repel nothing
  double safety_margin = 0.1;        // m beyond the rim: repulsion is at its full gain within it
  double max_speed = 1.0;            // m per step: the summed vector is clipped to this
  void validate() const;
};

// AuRA's motor schemas (Arkin 1989) on a ring of range readings. Each reading d (from the rim,
// along unit direction u) inside the sphere of influence S repels along -u with magnitude
// obstacle_gain * (S - d) / (S - m) for d > m, and obstacle_gain for d <= m (m the safety margin):
// AuRA's linear fall-off, capped. MOVE-TO-GOAL pulls with goal_gain toward the goal; NOISE adds
// noise_gain along a random direction drawn every noise_persistence steps. The vectors are summed
// and clipped to max_speed. The noise direction is state: one object per robot run.
class MotorSchemas {
 public:
  explicit MotorSchemas(SchemaSettings settings = {});
  const SchemaSettings& settings() const { return settings_; }

  // The velocity (m per step) at `position` toward `goal`, given readings[i] along directions[i].
  // Draws one uniform from `rng` when the noise direction is renewed.
  Eigen::Vector2d velocity(const Eigen::Vector2d& position, const Eigen::Vector2d& goal,
                           std::span<const double> readings, std::span<const Eigen::Vector2d> directions,
                           const SchemaParameters& p, core::Rng& rng);
  // The parts of the last velocity, for tests and figures.
  const Eigen::Vector2d& last_avoid() const { return avoid_; }
  const Eigen::Vector2d& last_goal() const { return goal_; }
  const Eigen::Vector2d& last_noise() const { return noise_; }
  // Forget the noise direction (a new world).
  void reset() { steps_held_ = -1; }

 private:
  SchemaSettings settings_;
  Eigen::Vector2d noise_direction_ = Eigen::Vector2d::UnitX();
  int steps_held_ = -1;  // < 0: draw a direction at the next step
  Eigen::Vector2d avoid_ = Eigen::Vector2d::Zero(), goal_ = Eigen::Vector2d::Zero(), noise_ = Eigen::Vector2d::Zero();
};

}  // namespace amp::nav
