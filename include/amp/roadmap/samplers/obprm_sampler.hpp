#pragma once
#include <memory>

#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

struct ObprmSamplerSettings {
  int max_attempts = 100;  // colliding seeds tried (free draws included) before sample() gives up
  int max_steps = 1000;    // steps walked along one ray before it is abandoned
  void validate() const;   // throws ParameterError
};

// Obstacle-based sampling (Amato, Bayazit, Dale, Jones & Vallejo 1998, OBPRM): draw a colliding
// configuration c, pick a random direction (towards a uniform state u) and walk from c at the space's
// resolution until the first free configuration, which lies within one resolution step of the
// obstacle's surface. A ray that reaches u, leaves the domain or exceeds max_steps is abandoned.
// One sample() may cost max_attempts x max_steps CD calls (100,000 by default: a fine resolution
// walks every ray to its end), so `stop` (optional) is polled between them and a stopped sample()
// gives up.
class ObprmSampler final : public Sampler {
 public:
  ObprmSampler(const core::Space& space, const world::ValidityChecker& checker, ObprmSamplerSettings settings = {},
               std::shared_ptr<const SamplingDomain> domain = nullptr, const core::StopCondition* stop = nullptr);
  bool sample(core::Rng& rng, State& out) override;

 private:
  const core::Space* space_;
  const world::ValidityChecker* checker_;
  ObprmSamplerSettings settings_;
  std::shared_ptr<const SamplingDomain> domain_;
  const core::StopCondition* stop_;
  State c_, target_, q_;
};

}  // namespace amp::roadmap
