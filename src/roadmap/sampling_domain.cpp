#include "amp/roadmap/sampling_domain.hpp"

#include "amp/core/error.hpp"
#include "amp/world/environment.hpp"

namespace amp::roadmap {

bool WholeSpaceDomain::sample(core::Rng& rng, State& out) const {
  space_->sample_uniform(rng, out);
  return true;
}

ReferencePointBoxDomain::ReferencePointBoxDomain(const core::Space& space, const world::Environment& environment,
                                                 Eigen::AlignedBox3d box)
    : space_(&space), environment_(&environment), box_(box), planar_(environment.workspace_dimension() == 2) {
  const int dims = planar_ ? 2 : 3;
  for (int i = 0; i < dims; ++i) {
    if (!(box_.min()[i] <= box_.max()[i])) {
      throw ParameterError("sampling region: empty box on axis " + std::to_string(i) + " [" +
                           std::to_string(box_.min()[i]) + ", " + std::to_string(box_.max()[i]) + "]");
    }
  }
}

bool ReferencePointBoxDomain::contains(const State& s) const {
  if (!space_->in_bounds(s)) return false;
  const Eigen::Vector3d p = environment_->reference_point(s);
  const int dims = planar_ ? 2 : 3;
  for (int i = 0; i < dims; ++i) {
    if (p[i] < box_.min()[i] || p[i] > box_.max()[i]) return false;
  }
  return true;
}

bool ReferencePointBoxDomain::sample(core::Rng& rng, State& out) const {
  for (int i = 0; i < kMaxDraws; ++i) {
    space_->sample_uniform(rng, out);
    if (contains(out)) return true;
  }
  return false;
}

std::shared_ptr<const SamplingDomain> domain_or_whole(std::shared_ptr<const SamplingDomain> domain,
                                                      const core::Space& space) {
  if (domain) return domain;
  return std::make_shared<WholeSpaceDomain>(space);
}

}  // namespace amp::roadmap
