#include "amp/nav/sins/parameter_policy.hpp"

#include <algorithm>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/sins/sins_plus_parameters.hpp"

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

namespace {
// One generic case: inputs in the middle of [0, 1], and as outputs the parameters each world starts
// from, so that the first recommendation is the static system's ("SINS would also start out with
// those same settings"); with the middle of the ranges, the paper's all-0.5 case.
learn::CaseLibrary first_library(const learn::CaseSettings& settings, const SchemaParameters& initial) {
  settings.validate();
  initial.validate();
  const auto length = static_cast<std::size_t>(settings.case_length);
  learn::CaseInputs generic;
  generic.fill(0.5);
  std::vector<learn::Case> cases(1);
  cases[0].inputs.assign(length, generic);
  cases[0].outputs.assign(length, initial.normalised());
  return learn::CaseLibrary(settings, std::move(cases));
}
}  // namespace

CaseBasedParameters::CaseBasedParameters(learn::CaseSettings settings, SchemaParameters initial,
                                         double stall_exploration)
    : library_(first_library(settings, initial)), history_(settings.case_length), initial_(initial), current_(initial),
      stall_exploration_(stall_exploration) {  // first_library validated the settings and `initial`
  const auto slots = static_cast<std::size_t>(settings.max_cases) * static_cast<std::size_t>(settings.case_length);
  if (settings.outcome_rate > 0.0) installed_sum_.assign(slots, learn::CaseOutputs{}), installed_count_.assign(slots, 0);
  if (!(stall_exploration >= 0.0 && stall_exploration <= 1.0)) {
    throw ParameterError("stall_exploration must be in [0, 1], got " + std::to_string(stall_exploration));
  }
}

SchemaParameters CaseBasedParameters::begin_world(core::Rng&) {
  history_.clear();
  std::fill(installed_count_.begin(), installed_count_.end(), 0);
  std::fill(installed_sum_.begin(), installed_sum_.end(), learn::CaseOutputs{});
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
  if (!installed_count_.empty()) {
    const int length = library_.settings().case_length;
    const auto slot = static_cast<std::size_t>(cycle.match.case_index * length +
                                               std::clamp(cycle.match.position, 0, length - 1));
    for (int x = 0; x < learn::kCaseOutputs; ++x) installed_sum_[slot][x] += next[x];
    ++installed_count_[slot];
  }
  cycle.relative_similarity = library_.relative_similarity(cycle.match);
  cycle.learned = library_.learn(cycle.match, history_);
  last_ = cycle;
  current_ = SchemaParameters::from_normalised(next);
  return current_;
}

void CaseBasedParameters::end_world(bool solved, double steps_fraction) {
  if (installed_count_.empty()) return;
  const double r = solved ? 1.0 - std::clamp(steps_fraction, 0.0, 1.0) : 0.0;
  if (!has_baseline_) baseline_ = r, has_baseline_ = true;
  const double advantage = r - baseline_;
  baseline_ += kBaselineRate * (r - baseline_);
  const int length = library_.settings().case_length;
  for (std::size_t slot = 0; slot < installed_count_.size(); ++slot) {
    if (installed_count_[slot] == 0) continue;
    learn::CaseOutputs mean = installed_sum_[slot];
    for (double& v : mean) v /= installed_count_[slot];
    library_.shift_outputs(static_cast<int>(slot) / length, static_cast<int>(slot) % length, mean,
                           library_.settings().outcome_rate * advantage);
    installed_count_[slot] = 0;
    installed_sum_[slot] = learn::CaseOutputs{};
  }
}

std::unique_ptr<ParameterPolicy> make_parameter_policy(const std::string& system, const learn::CaseSettings& cases,
                                                       const SchemaParameters& initial, double stall_exploration,
                                                       const learn::SplittingCaseSettings& plus) {
  if (system == "static") return std::make_unique<StaticParameters>(initial);
  if (system == "random") return std::make_unique<RandomParameters>();
  if (system == "adaptive" || system == "sins") return std::make_unique<CaseBasedParameters>(cases, initial, stall_exploration);
  if (system == "sins-plus") return std::make_unique<SplittingCaseParameters>(plus, initial);
  throw ParameterError("unknown system '" + system + "' (systems: static, random, adaptive, sins-plus)");
}

}  // namespace amp::nav
