#include "amp/roadmap/samplers/obprm_sampler.hpp"

#include <string>

#include "amp/core/error.hpp"

namespace amp::roadmap {

void ObprmSamplerSettings::validate() const {
  if (max_attempts < 1) {
    throw ParameterError("obprm sampler: max_attempts must be >= 1, got " + std::to_string(max_attempts));
  }
  if (max_steps < 1) throw ParameterError("obprm sampler: max_steps must be >= 1, got " + std::to_string(max_steps));
}

ObprmSampler::ObprmSampler(const core::Space& space, const world::ValidityChecker& checker,
                           ObprmSamplerSettings settings, std::shared_ptr<const SamplingDomain> domain,
                           const core::StopCondition* stop)
    : space_(&space), checker_(&checker), settings_(settings), domain_(domain_or_whole(std::move(domain), space)),
      stop_(stop) {
  settings_.validate();
}

bool ObprmSampler::sample(core::Rng& rng, State& out) {
  const double step = space_->resolution();
  core::StopPoll poll(stop_);
  if (poll.fired()) return false;
  for (int i = 0; i < settings_.max_attempts; ++i) {
    if (!domain_->sample(rng, c_)) return false;
    if (poll.step()) return false;
    if (checker_->is_valid(c_)) continue;  // OBPRM starts inside an obstacle
    space_->sample_uniform(rng, target_);
    const double dist = space_->distance(c_, target_);
    for (int s = 1; s <= settings_.max_steps; ++s) {
      const double t = s * step / dist;
      if (!(t <= 1.0)) break;  // walked past u (or dist = 0): abandon the ray
      space_->interpolate(c_, target_, t, q_);
      if (!domain_->contains(q_)) break;
      if (poll.step()) return false;
      if (checker_->is_valid(q_)) {
        out = q_;
        return true;
      }
    }
  }
  return false;
}

}  // namespace amp::roadmap
