#pragma once
#include <memory>

#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// Rejection sampling of free states uniform in a domain (a UAS region), the uniform member of a
// Hybrid PRM sampler set. On the whole space it draws exactly what UniformSampler draws.
class UniformDomainSampler final : public Sampler {
 public:
  static constexpr int kDefaultMaxAttempts = 100;  // as UniformSamplerSettings

  UniformDomainSampler(std::shared_ptr<const SamplingDomain> domain, const world::ValidityChecker& checker,
                       int max_attempts = kDefaultMaxAttempts);
  bool sample(core::Rng& rng, State& out) override;

 private:
  std::shared_ptr<const SamplingDomain> domain_;
  const world::ValidityChecker* checker_;
  int max_attempts_;
};

}  // namespace amp::roadmap
