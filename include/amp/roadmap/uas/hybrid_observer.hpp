#pragma once
#include <map>
#include <memory>
#include <string>

#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/uas/sample_learner.hpp"

namespace amp::roadmap {

// Feeds every sampled insertion's reward to a SampleLearner and counts node classes; reports both.
class HybridObserver final : public InsertionObserver {
 public:
  explicit HybridObserver(SampleLearner& sampler, std::map<std::string, double> constants = {})
      : sampler_(&sampler), classes_(std::move(constants)) {}
  void inserted(const Roadmap& roadmap, const Insertion& insertion) override;
  void report(std::map<std::string, double>& extra) const override;

 private:
  SampleLearner* sampler_;
  NodeClassCounter classes_;
};

// A learning sampler (Sampler and SampleLearner) with the HybridObserver that teaches it, ready for
// PrmParts::observed_sampler; `constants` are reported as they are.
template <class LearningSampler>
ObservedSampler with_hybrid_observer(std::unique_ptr<LearningSampler> sampler,
                                     std::map<std::string, double> constants = {}) {
  auto observer = std::make_unique<HybridObserver>(*sampler, std::move(constants));
  return ObservedSampler{std::move(sampler), std::move(observer)};
}

}  // namespace amp::roadmap
