#pragma once
#include <memory>

#include "amp/core/space.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

struct BridgeSamplerSettings {
  double d = 1.0;            // standard deviation of the bridge length (space metric); > 0
  int max_attempts = 100;     // bridges tried before sample() gives up
  // Hsu et al.'s hybrid bridge sampler: each call is a plain uniform sample with this probability,
  // so that open regions are covered too. 0 = the bridge test alone.
  double uniform_mix = 0.0;
  void validate() const;  // throws ParameterError
};

// The bridge test (Hsu, Jiang, Reif & Sun 2003): q1 uniform and colliding, q2 at a distance |N(0, d)|
// from q1 along a random direction and colliding too, keep their midpoint if it is free: a short
// "bridge" across a narrow passage. Costs 1 CD call for a free q1, 2 for a free q2, 3 otherwise.
class BridgeSampler final : public Sampler {
 public:
  BridgeSampler(const core::Space& space, const world::ValidityChecker& checker, BridgeSamplerSettings settings,
                std::shared_ptr<const SamplingDomain> domain = nullptr);
  bool sample(core::Rng& rng, State& out) override;

 private:
  bool uniform(core::Rng& rng, State& out);

  const core::Space* space_;
  const world::ValidityChecker* checker_;
  BridgeSamplerSettings settings_;
  std::shared_ptr<const SamplingDomain> domain_;
  State q1_, q2_, mid_;
};

}  // namespace amp::roadmap
