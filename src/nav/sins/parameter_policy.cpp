#include "amp/nav/sins/parameter_policy.hpp"

#include <algorithm>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::nav {

StaticParameters::StaticParameters(SchemaParameters p) : p_(p) { p_.validate(); }

SchemaParameters RandomParameters::draw(core::Rng& rng) {
  SchemaParameters p;
  p.obstacle_gain = rng.uniform(SchemaParameters::kObstacleGain.lo, SchemaParameters::kObstacleGain.hi);
  p.goal_gain = rng.uniform(SchemaParameters::kGoalGain.lo, SchemaParameters::kGoalGain.hi);
  p.noise_gain = rng.uniform(SchemaParameters::kNoiseGain.lo, SchemaParameters::kNoiseGain.hi);
  p.noise_persistence = rng.uniform(SchemaParameters::kNoisePersistence.lo, SchemaParameters::kNoisePersistence.hi);
  return p;
}

CaseBasedParameters::CaseBasedParameters(learn::CaseSettings settings, SchemaParameters initial,
                                         double stall_exploration)
    : library_(settings), history_(settings.case_length), initial_(initial), current_(initial),
      stall_exploration_(stall_exploration) {
  initial_.validate();
  if (!(stall_exploration >= 0.0 && stall_exploration <= 1.0)) {
    throw ParameterError("stall_exploration must be in [0, 1], got " + std::to_string(stall_exploration));
  }
}

SchemaParameters CaseBasedParameters::begin_world(core::Rng&) {
  history_.clear();
  current_ = initial_;
  return current_;
}

SchemaParameters CaseBasedParameters::end_interval(const learn::CaseInputs& inputs, core::Rng& rng) {
  // Perceive: what was sensed over the interval, beside the parameters that produced it, and
  // their reward: the progress toward the goal they made (Motion-Towards-Goal above its neutral 0.5,
  // at full speed 1), for reward-weighted reinforcement.
  const double progress = std::clamp(2.0 * (inputs[3] - 0.5), 0.0, 1.0);
  history_.push(inputs, current_.normalised(), progress);
  CaseCycle cycle;
  cycle.match = library_.retrieve(history_);
  const learn::CaseOutputs next = library_.adapt(cycle.match, rng, stall_exploration_ * (1.0 - progress));
  cycle.relative_similarity = library_.relative_similarity(cycle.match);
  cycle.learned = library_.learn(cycle.match, history_);
  last_ = cycle;
  current_ = SchemaParameters::from_normalised(next);
  return current_;
}

std::unique_ptr<ParameterPolicy> make_parameter_policy(const std::string& system, const learn::CaseSettings& cases,
                                                       const SchemaParameters& initial, double stall_exploration) {
  if (system == "static") return std::make_unique<StaticParameters>(initial);
  if (system == "random") return std::make_unique<RandomParameters>();
  if (system == "adaptive" || system == "sins") return std::make_unique<CaseBasedParameters>(cases, initial, stall_exploration);
  throw ParameterError("unknown system '" + system + "' (systems: static, random, adaptive)");
}

}  // namespace amp::nav
