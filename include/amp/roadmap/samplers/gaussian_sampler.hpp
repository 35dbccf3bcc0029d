#pragma once
#include <memory>

#include "amp/core/space.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

struct GaussianSamplerSettings {
  double d = 1.0;         // standard deviation of the pair's distance (space metric); > 0
  int max_attempts = 100;  // pairs drawn before sample() gives up (2 CD calls each)
  void validate() const;  // throws ParameterError
};

// Gaussian sampling (Boor, Overmars & van der Stappen 1999): q1 uniform, q2 at a distance |N(0, d)|
// from q1 along a random direction; when exactly one of the two is free, keep the free one. Samples
// thus lie within about d of an obstacle surface. q1 is drawn in the domain, and a free q2 outside the
// domain is redrawn before any CD call, so every sample lies in the domain.
class GaussianSampler final : public Sampler {
 public:
  GaussianSampler(const core::Space& space, const world::ValidityChecker& checker, GaussianSamplerSettings settings,
                  std::shared_ptr<const SamplingDomain> domain = nullptr);
  bool sample(core::Rng& rng, State& out) override;

 private:
  const core::Space* space_;
  const world::ValidityChecker* checker_;
  GaussianSamplerSettings settings_;
  std::shared_ptr<const SamplingDomain> domain_;
  State q1_, q2_;
};

}  // namespace amp::roadmap
