#include "amp/roadmap/uas/hybrid_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"

namespace amp::roadmap {

const core::SettingsSchema<HybridSettings>& HybridSettings::schema() {
  using S = HybridSettings;
  static const core::SettingsSchema<S> schema(
      "hybrid prm",
      {core::real_field<S>("gamma", &S::gamma, 1e-6, 1, "share of random sampler selection"),
       core::real_field<S>("alpha", &S::alpha, 1e-6, 1000, "reward exp(-alpha v^2) of non-structural nodes"),
       core::enum_field<S>("cost", &S::cost,
                           std::vector<std::pair<std::string, SampleCost>>{{"node", SampleCost::kNode},
                                                                           {"sampling", SampleCost::kSampling}},
                           "a sample's cost: CD calls to sample and connect it (node) or to sample it only")});
  return schema;
}

namespace {
std::size_t checked_size(const std::vector<HybridSampler::Arm>& arms) {
  for (const auto& a : arms) {
    if (!a.sampler) throw ParameterError("hybrid prm: sampler '" + a.name + "' is missing");
  }
  return arms.size();
}
}  // namespace

HybridSampler::HybridSampler(std::vector<Arm> arms, const world::ValidityChecker& checker, HybridSettings settings)
    : arms_(std::move(arms)),
      checker_(&checker),
      settings_(settings),
      bandit_(checked_size(arms_), settings.gamma),
      samples_(arms_.size(), 0),
      chosen_(arms_.size(), 0) {
  settings_.validate();
}

double HybridSampler::normalised_cost(std::uint64_t cd_calls) {
  const std::uint64_t c = std::max<std::uint64_t>(cd_calls, 1);
  total_cost_ += c;
  ++total_samples_;
  const double mean = static_cast<double>(total_cost_) / static_cast<double>(total_samples_);
  return static_cast<double>(c) / mean;
}

bool HybridSampler::sample(core::Rng& rng, State& out) {
  const std::size_t s = bandit_.choose(rng);
  ++chosen_[s];
  const std::uint64_t before = checker_->counters().cd_calls();
  const bool ok = arms_[s].sampler->sample(rng, out);
  if (!ok) {
    bandit_.update(s, 0.0, normalised_cost(checker_->counters().cd_calls() - before));
    pending_ = false;
    return false;
  }
  ++samples_[s];
  last_arm_ = s;
  sampling_cd_calls_ = checker_->counters().cd_calls() - before;
  cd_at_sample_ = before;
  pending_ = true;
  return true;
}

double HybridSampler::reward(const Insertion& insertion) const {
  switch (classify(insertion)) {
    case NodeClass::kCreate:
    case NodeClass::kMerge: return 1.0;
    case NodeClass::kExpand:
    case NodeClass::kOversample: break;
  }
  const double v = insertion.visibility();
  return std::exp(-settings_.alpha * v * v);
}

void HybridSampler::reward_last(const Insertion& insertion) {
  if (!pending_) return;  // nothing sampled since the last reward (e.g. a seed)
  last_cd_calls_ = settings_.cost == SampleCost::kNode ? checker_->counters().cd_calls() - cd_at_sample_
                                                      : sampling_cd_calls_;
  last_reward_ = reward(insertion);
  bandit_.update(last_arm_, last_reward_, normalised_cost(last_cd_calls_));
  pending_ = false;
}

void HybridSampler::report(std::map<std::string, double>& extra) const {
  for (std::size_t s = 0; s < arms_.size(); ++s) {
    extra["prob_" + arms_[s].name] = bandit_.probabilities()[s];
    extra["samples_" + arms_[s].name] = static_cast<double>(samples_[s]);
    extra["chosen_" + arms_[s].name] = static_cast<double>(chosen_[s]);
  }
}

void HybridSampler::observe(const Roadmap& roadmap, const Insertion& insertion) {
  for (Arm& a : arms_) {
    if (a.observer != nullptr) a.observer->inserted(roadmap, insertion);
  }
}

}  // namespace amp::roadmap
