#include "amp/roadmap/samplers/gaussian_sampler.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"

namespace amp::roadmap {

void GaussianSamplerSettings::validate() const {
  validate_offset_settings("gaussian", d, max_attempts);
}

GaussianSampler::GaussianSampler(const core::Space& space, const world::ValidityChecker& checker,
                                 GaussianSamplerSettings settings, std::shared_ptr<const SamplingDomain> domain)
    : space_(&space), checker_(&checker), settings_(settings), domain_(domain_or_whole(std::move(domain), space)) {
  settings_.validate();
}

bool GaussianSampler::sample(core::Rng& rng, State& out) {
  for (int i = 0; i < settings_.max_attempts; ++i) {
    if (!domain_->sample(rng, q1_)) return false;
    random_offset(*space_, rng, q1_, std::abs(rng.normal(0.0, settings_.d)), q2_);
    if (!domain_->contains(q2_)) continue;  // no CD call spent
    const bool free1 = checker_->is_valid(q1_);
    const bool free2 = checker_->is_valid(q2_);
    if (free1 != free2) {
      out = free1 ? q1_ : q2_;
      return true;
    }
  }
  return false;
}

}  // namespace amp::roadmap
