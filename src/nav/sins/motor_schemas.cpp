#include "amp/nav/sins/motor_schemas.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::nav {

namespace {

void check(double v, SchemaParameters::Range r, const char* name) {
  if (!(v >= r.lo && v <= r.hi)) {
    throw ParameterError(std::string(name) + " must be in [" + std::to_string(r.lo) + ", " + std::to_string(r.hi) +
                         "], got " + std::to_string(v));
  }
}

double to_unit(double v, SchemaParameters::Range r) { return (v - r.lo) / (r.hi - r.lo); }
double from_unit(double u, SchemaParameters::Range r) { return r.lo + std::clamp(u, 0.0, 1.0) * (r.hi - r.lo); }

}  // namespace

SchemaParameters SchemaParameters::middle() { return from_normalised({0.5, 0.5, 0.5, 0.5}); }

const core::SettingsSchema<SchemaParameters>& SchemaParameters::schema() {
  using S = SchemaParameters;
  static const core::SettingsSchema<S> schema(
      "schema_parameters",
      {core::real_field<S>("obstacle_gain", &S::obstacle_gain, kObstacleGain.lo, kObstacleGain.hi,
                           "AVOID-STATIC-OBSTACLE's gain (the static system's, and where the adaptive one starts)"),
       core::real_field<S>("goal_gain", &S::goal_gain, kGoalGain.lo, kGoalGain.hi, "MOVE-TO-GOAL's gain"),
       core::real_field<S>("noise_gain", &S::noise_gain, kNoiseGain.lo, kNoiseGain.hi, "NOISE's gain"),
       core::real_field<S>("noise_persistence", &S::noise_persistence, kNoisePersistence.lo, kNoisePersistence.hi,
                           "steps a noise direction is held")});
  return schema;
}

void SchemaParameters::validate() const {
  check(obstacle_gain, kObstacleGain, "obstacle_gain");
  check(goal_gain, kGoalGain, "goal_gain");
  check(noise_gain, kNoiseGain, "noise_gain");
  check(noise_persistence, kNoisePersistence, "noise_persistence");
}

std::array<double, 4> SchemaParameters::normalised() const {
  return {to_unit(obstacle_gain, kObstacleGain), to_unit(goal_gain, kGoalGain), to_unit(noise_gain, kNoiseGain),
          to_unit(noise_persistence, kNoisePersistence)};
}

SchemaParameters SchemaParameters::from_normalised(const std::array<double, 4>& u) {
  return {from_unit(u[0], kObstacleGain), from_unit(u[1], kGoalGain), from_unit(u[2], kNoiseGain),
          from_unit(u[3], kNoisePersistence)};
}

void SchemaSettings::validate() const {
  if (!(safety_margin >= 0.0) || !std::isfinite(safety_margin)) {
    throw ParameterError("safety_margin must be >= 0, got " + std::to_string(safety_margin));
  }
  if (!(sphere_of_influence > safety_margin) || !std::isfinite(sphere_of_influence)) {
    throw ParameterError("sphere_of_influence must be > safety_margin, got " + std::to_string(sphere_of_influence));
  }
  if (!(max_speed > 0.0) || !std::isfinite(max_speed)) throw ParameterError("max_speed must be > 0, got " + std::to_string(max_speed));
}

MotorSchemas::MotorSchemas(SchemaSettings settings) : settings_(settings) { settings_.validate(); }

Eigen::Vector2d MotorSchemas::velocity(const Eigen::Vector2d& position, const Eigen::Vector2d& goal,
                                       std::span<const double> readings, std::span<const Eigen::Vector2d> directions,
                                       const SchemaParameters& p, core::Rng& rng) {
  const SchemaSettings& s = settings_;
  avoid_.setZero();
  for (std::size_t i = 0; i < readings.size() && i < directions.size(); ++i) {
    const double d = readings[i];
    if (!(d < s.sphere_of_influence)) continue;
    const double m = d <= s.safety_margin ? 1.0 : (s.sphere_of_influence - d) / (s.sphere_of_influence - s.safety_margin);
    avoid_ -= p.obstacle_gain * m * directions[i];
  }
  const Eigen::Vector2d to_goal = goal - position;
  goal_ = to_goal.squaredNorm() > 0.0 ? Eigen::Vector2d(p.goal_gain * to_goal.normalized()) : Eigen::Vector2d::Zero();
  // NOISE: a direction held for noise_persistence steps (rounded), then drawn afresh.
  const int hold = std::max(1, static_cast<int>(std::lround(p.noise_persistence)));
  if (steps_held_ < 0 || steps_held_ >= hold) {
    const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
    noise_direction_ = Eigen::Vector2d(std::cos(a), std::sin(a));
    steps_held_ = 0;
  }
  ++steps_held_;
  noise_ = p.noise_gain * noise_direction_;
  Eigen::Vector2d v = avoid_ + goal_ + noise_;
  const double n = v.norm();
  if (n > s.max_speed) v *= s.max_speed / n;
  return v;
}

}  // namespace amp::nav
