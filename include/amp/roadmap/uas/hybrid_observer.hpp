#pragma once
#include <map>
#include <string>

#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/prm/node_classifier.hpp"
#include "amp/roadmap/uas/adaptive_sampler.hpp"

namespace amp::roadmap {

// Feeds every sampled insertion's reward to an AdaptiveSampler and counts node classes; reports both.
class HybridObserver final : public InsertionObserver {
 public:
  explicit HybridObserver(AdaptiveSampler& sampler, std::map<std::string, double> constants = {})
      : sampler_(&sampler), classes_(std::move(constants)) {}
  void inserted(const Roadmap& roadmap, const Insertion& insertion) override;
  void report(std::map<std::string, double>& extra) const override;

 private:
  AdaptiveSampler* sampler_;
  NodeClassCounter classes_;
};

}  // namespace amp::roadmap
