#include "amp/roadmap/samplers/sampling_domain.hpp"

#include "amp/core/error.hpp"
#include "amp/world/planning_features.hpp"

namespace amp::roadmap {

DrawSequence parse_draw_sequence(const std::string& name) {
  if (name == "random") return DrawSequence::kRandom;
  if (name == "halton") return DrawSequence::kHalton;
  throw ParameterError("unknown draw sequence '" + name + "' (random or halton)");
}

void StateDrawer::draw(core::Rng& rng, State& out) {
  if (sequence_ == DrawSequence::kRandom) {
    space_->sample_uniform(rng, out);
    return;
  }
  if (!halton_) {
    halton_.emplace(space_->unit_dimension(), rng);
    u_.resize(static_cast<std::size_t>(space_->unit_dimension()));
  }
  halton_->next(u_.data());
  space_->from_unit(u_.data(), out);
}

bool WholeSpaceDomain::sample(core::Rng& rng, State& out) const {
  drawer_.draw(rng, out);
  return true;
}

ReferencePointBoxDomain::ReferencePointBoxDomain(const core::Space& space, const world::PlanningFeatures& features,
                                                 Eigen::AlignedBox3d box, DrawSequence sequence)
    : space_(&space),
      features_(&features),
      box_(box),
      planar_(features.workspace_dimension() == 2),
      drawer_(space, sequence) {
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
  const Eigen::Vector3d p = features_->reference_point(s);
  const int dims = planar_ ? 2 : 3;
  for (int i = 0; i < dims; ++i) {
    if (p[i] < box_.min()[i] || p[i] > box_.max()[i]) return false;
  }
  return true;
}

bool ReferencePointBoxDomain::sample(core::Rng& rng, State& out) const {
  for (int i = 0; i < kMaxDraws; ++i) {
    drawer_.draw(rng, out);
    if (contains(out)) return true;
  }
  return false;
}

std::shared_ptr<const SamplingDomain> domain_or_whole(std::shared_ptr<const SamplingDomain> domain,
                                                      const core::Space& space, DrawSequence sequence) {
  if (domain) return domain;
  return std::make_shared<WholeSpaceDomain>(space, sequence);
}

}  // namespace amp::roadmap
