#include "amp/roadmap/samplers/bridge_sampler.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"

namespace amp::roadmap {

void BridgeSamplerSettings::validate() const {
  validate_offset_settings("bridge", d, max_attempts);
  if (!(uniform_mix >= 0.0 && uniform_mix <= 1.0)) {
    throw ParameterError("bridge sampler: uniform_mix must be in [0, 1], got " + std::to_string(uniform_mix));
  }
}

BridgeSampler::BridgeSampler(const core::Space& space, const world::ValidityChecker& checker,
                             BridgeSamplerSettings settings, std::shared_ptr<const SamplingDomain> domain)
    : space_(&space), checker_(&checker), settings_(settings), domain_(domain_or_whole(std::move(domain), space)) {
  settings_.validate();
}

bool BridgeSampler::uniform(core::Rng& rng, State& out) {
  for (int i = 0; i < settings_.max_attempts; ++i) {
    if (!domain_->sample(rng, out)) return false;
    if (checker_->is_valid(out)) return true;
  }
  return false;
}

bool BridgeSampler::sample(core::Rng& rng, State& out) {
  // The mix draw is made only when mixing is on, so uniform_mix = 0 consumes no extra random number.
  if (settings_.uniform_mix > 0.0 && rng.uniform01() < settings_.uniform_mix) return uniform(rng, out);
  for (int i = 0; i < settings_.max_attempts; ++i) {
    if (!domain_->sample(rng, q1_)) return false;
    if (checker_->is_valid(q1_)) continue;
    random_offset(*space_, rng, q1_, std::abs(rng.normal(0.0, settings_.d)), q2_);
    if (checker_->is_valid(q2_)) continue;
    space_->interpolate(q1_, q2_, 0.5, mid_);
    if (!domain_->contains(mid_)) continue;
    if (checker_->is_valid(mid_)) {
      out = mid_;
      return true;
    }
  }
  return false;
}

}  // namespace amp::roadmap
