#include "amp/roadmap/samplers/expansion_sampler.hpp"

#include <algorithm>
#include <cmath>

#include "amp/roadmap/samplers/random_offset.hpp"

namespace amp::roadmap {

void ExpansionSamplerSettings::validate() const {
  validate_offset_settings("expansion", d, max_attempts);
}

ExpansionSampler::ExpansionSampler(const core::Space& space, const world::ValidityChecker& checker,
                                   ExpansionSamplerSettings settings, std::shared_ptr<const SamplingDomain> domain)
    : space_(&space), checker_(&checker), settings_(settings), domain_(domain_or_whole(std::move(domain), space)) {
  settings_.validate();
}

void ExpansionSampler::add(const State& state, double visibility) {
  const double weight = 1.0 - std::clamp(visibility, 0.0, 1.0);
  if (!(weight > 0.0) || !domain_->contains(state)) return;
  states_.push_back(state);
  cumulative_.push_back((cumulative_.empty() ? 0.0 : cumulative_.back()) + weight);
}

void ExpansionSampler::add(const VisibleNodes& nodes) {
  if (!nodes.roadmap) return;
  const std::size_t n = std::min(nodes.roadmap->vertex_count(), nodes.visibility.size());
  for (std::size_t v = 0; v < n; ++v) add(nodes.roadmap->state(static_cast<VertexId>(v)), nodes.visibility[v]);
}

void ExpansionSampler::inserted(const Roadmap& roadmap, const Insertion& insertion) {
  add(roadmap.state(insertion.vertex), insertion.visibility());
}

bool ExpansionSampler::sample(core::Rng& rng, State& out) {
  if (states_.empty()) return false;
  for (int i = 0; i < settings_.max_attempts; ++i) {
    // Roulette wheel over the failure ratios, by binary search of the prefix sums.
    const double u = rng.uniform(0.0, cumulative_.back());
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
    const std::size_t node = std::min<std::size_t>(static_cast<std::size_t>(it - cumulative_.begin()), states_.size() - 1);
    random_offset(*space_, rng, states_[node], std::abs(rng.normal(0.0, settings_.d)), q_);
    if (!domain_->contains(q_)) continue;  // no CD call spent
    if (checker_->is_valid(q_)) {
      out = q_;
      return true;
    }
  }
  return false;
}

}  // namespace amp::roadmap
