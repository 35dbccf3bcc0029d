#pragma once
#include "amp/core/space.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

struct UniformSamplerSettings {
  // Draws before sample() gives up; bounds the time one call can take in a nearly full space.
  int max_attempts = 100;
  void validate() const;  // throws ParameterError unless max_attempts >= 1
};

// Rejection sampling: uniform states of the space until one is free.
class UniformSampler final : public Sampler {
 public:
  UniformSampler(const core::Space& space, const world::ValidityChecker& checker,
                 UniformSamplerSettings settings = {});
  bool sample(core::Rng& rng, State& out) override;

 private:
  const core::Space* space_;
  const world::ValidityChecker* checker_;
  UniformSamplerSettings settings_;
};

}  // namespace amp::roadmap
