#include "amp/roadmap/samplers/uniform_domain_sampler.hpp"

#include <stdexcept>
#include <string>

#include "amp/core/error.hpp"

namespace amp::roadmap {

UniformDomainSampler::UniformDomainSampler(std::shared_ptr<const SamplingDomain> domain,
                                           const world::ValidityChecker& checker, int max_attempts)
    : domain_(std::move(domain)), checker_(&checker), max_attempts_(max_attempts) {
  if (!domain_) throw std::logic_error("UniformDomainSampler: null domain");
  if (max_attempts_ < 1) {
    throw ParameterError("uniform sampler: max_attempts must be >= 1, got " + std::to_string(max_attempts_));
  }
}

bool UniformDomainSampler::sample(core::Rng& rng, State& out) {
  for (int i = 0; i < max_attempts_; ++i) {
    if (!domain_->sample(rng, out)) return false;
    if (checker_->is_valid(out)) return true;
  }
  return false;
}

}  // namespace amp::roadmap
