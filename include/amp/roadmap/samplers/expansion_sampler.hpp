#pragma once
#include <memory>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/samplers/sampler.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

// Roadmap nodes with the visibility each was measured at, known before a run's insertions (UAS's
// training roadmap when the planning roadmap starts from it).
struct VisibleNodes {
  std::shared_ptr<const Roadmap> roadmap;
  std::vector<double> visibility;  // per vertex of roadmap
};

struct ExpansionSamplerSettings {
  double d = 1.0;          // standard deviation of the step from the chosen node (space metric); > 0
  int max_attempts = 20;   // steps tried before sample() gives up (1 CD call each)
  void validate() const;   // throws ParameterError
};

// The expansion step of PRM (Kavraki, Svestka, Latombe & Overmars 1996, section 3.2), as a sampler: a
// roadmap node is chosen with probability proportional to its failure ratio 1 - visibility (the share
// of its connection attempts that failed: nodes in narrow space, at a passage's mouth), and the
// sample is a free state a distance |N(0, d)| from it along a random direction.
//
// Why (beyond the papers): samplers that draw each state afresh wait for a narrow passage like a
// geometric waiting time, whose spread is as large as its mean; growing the roadmap from nodes
// already inside a passage was meant to change that. Measured, it did not (docs/uas.md, "What else
// was tried against the CV": 3-12% dearer, CV unchanged), so Hybrid PRM and UAS keep it off.
//
// It learns its candidates by observing insertions (the run's PRM tells it through the adaptive
// sampler that owns it); nodes whose reference point lies outside the domain are not candidates.
// With no candidate of positive weight, sample() fails at no CD call.
class ExpansionSampler final : public Sampler, public InsertionObserver {
 public:
  ExpansionSampler(const core::Space& space, const world::ValidityChecker& checker, ExpansionSamplerSettings settings,
                   std::shared_ptr<const SamplingDomain> domain = nullptr);
  bool sample(core::Rng& rng, State& out) override;
  // Offers the inserted vertex with its visibility at insertion.
  void inserted(const Roadmap& roadmap, const Insertion& insertion) override;
  // Offers a node known before the run's insertions.
  void add(const State& state, double visibility);
  void add(const VisibleNodes& nodes);
  std::size_t candidates() const { return states_.size(); }

 private:
  const core::Space* space_;
  const world::ValidityChecker* checker_;
  ExpansionSamplerSettings settings_;
  std::shared_ptr<const SamplingDomain> domain_;
  std::vector<State> states_;       // candidates with weight > 0
  std::vector<double> cumulative_;  // prefix sums of their weights (weights never change: append only)
  State q_;
};

}  // namespace amp::roadmap
