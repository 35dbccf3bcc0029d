#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/settings_schema.hpp"
#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/uas/sample_learner.hpp"
#include "amp/roadmap/uas/sampler_bandit.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// What a sample's cost counts (the UAS paper: the CD calls the sample took).
enum class SampleCost : std::uint8_t {
  // Sampling and connecting: every CD call between drawing the sample and its insertion. This is
  // what the node cost the planner, and it keeps cheap-to-draw samplers from winning on cost alone
  // (uniform draws cost ~1 CD call, Gaussian and OBPRM 5-20, but connecting any of them to k
  // neighbours costs 10-100x more: with sampling cost only, Hybrid PRM settled on uniform, see
  // docs/uas.md).
  kNode = 0,
  kSampling = 1,  // sampling only (the sampler's own CD calls)
};

struct HybridSettings {
  double gamma = 0.5;  // share of random selection (UAS: equal weight to past performance and chance)
  double alpha = 4.0;  // UAS reward exp(-alpha * v^2) for cc-expand / cc-oversample nodes
  SampleCost cost = SampleCost::kNode;
  // gamma, alpha and cost, as hybrid-prm and uas take them.
  static const core::SettingsSchema<HybridSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

// One Hybrid PRM sampler set: a bandit over named samplers (Hsu, Sanchez-Ante & Sun 2005) rewarded by
// the structural effect of each sample (UAS). sample() chooses a sampler and measures the CD calls it
// spends; after PRM has inserted the sample, reward_last() updates the chosen sampler's weight. UAS
// runs one HybridSampler per region, each over samplers restricted to that region's box.
//
// Cost: the sample's CD calls (settings.cost says which) divided by the running mean of those costs in
// this set (this one included), so that costs are near 1 and rhat is on the reward's scale; a sample
// that spent no CD call counts as one. A failed sample costs its sampling CD calls.
class HybridSampler final : public Sampler, public SampleLearner {
 public:
  struct Arm {
    std::string name;
    std::unique_ptr<Sampler> sampler;
    // The same sampler when it also observes insertions (ExpansionSampler), else null. Not owning.
    InsertionObserver* observer = nullptr;
  };

  // Throws ParameterError for bad settings or no arms.
  HybridSampler(std::vector<Arm> arms, const world::ValidityChecker& checker, HybridSettings settings = {});

  // A sample of the chosen sampler. When it fails, the arm is updated at once with reward 0 (which
  // leaves its weight as it was: EXP3 updates only by the reward).
  bool sample(core::Rng& rng, State& out) override;
  // The UAS reward of the last sample, now inserted: 1 for cc-create / cc-merge, exp(-alpha v^2) else.
  void reward_last(const Insertion& insertion) override;
  // Tells the observing arms.
  void observe(const Roadmap& roadmap, const Insertion& insertion) override;
  // The reward and raw cost (CD calls, as settings.cost counts them) of the last rewarded sample.
  double last_reward() const { return last_reward_; }
  std::uint64_t last_cd_calls() const { return last_cd_calls_; }
  double reward(const Insertion& insertion) const;

  const SamplerBandit& bandit() const { return bandit_; }
  const std::string& arm_name(std::size_t s) const { return arms_[s].name; }
  std::uint64_t samples(std::size_t s) const { return samples_[s]; }  // successful samples of arm s
  std::uint64_t chosen(std::size_t s) const { return chosen_[s]; }    // times arm s was chosen
  // Normalised cost of a sample that spent `cd_calls` (updates the running mean).
  double normalised_cost(std::uint64_t cd_calls);
  // prob_<name>, samples_<name>, chosen_<name> for every arm.
  void report(std::map<std::string, double>& extra) const override;

 private:
  std::vector<Arm> arms_;
  const world::ValidityChecker* checker_;
  HybridSettings settings_;
  SamplerBandit bandit_;
  std::vector<std::uint64_t> samples_, chosen_;
  std::uint64_t total_cost_ = 0, total_samples_ = 0;
  std::size_t last_arm_ = 0;
  bool pending_ = false;                  // a successful sample awaits its reward
  std::uint64_t cd_at_sample_ = 0;       // the CD count when the pending sample was drawn
  std::uint64_t sampling_cd_calls_ = 0;  // the pending sample's own CD calls
  double last_reward_ = 0.0;
  std::uint64_t last_cd_calls_ = 0;
};

}  // namespace amp::roadmap
