#include "amp/roadmap/samplers/uniform_sampler.hpp"

#include <string>

#include "amp/core/error.hpp"

namespace amp::roadmap {

void UniformSamplerSettings::validate() const {
  if (max_attempts < 1) {
    throw ParameterError("uniform sampler: max_attempts must be >= 1, got " + std::to_string(max_attempts));
  }
}

UniformSampler::UniformSampler(const core::Space& space, const world::ValidityChecker& checker,
                               UniformSamplerSettings settings)
    : space_(&space), checker_(&checker), settings_(settings) {
  settings_.validate();
}

bool UniformSampler::sample(core::Rng& rng, State& out) {
  for (int i = 0; i < settings_.max_attempts; ++i) {
    space_->sample_uniform(rng, out);
    if (checker_->is_valid(out)) return true;
  }
  return false;
}

}  // namespace amp::roadmap
