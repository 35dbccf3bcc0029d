#pragma once
#include <memory>
#include <vector>

#include "amp/roadmap/samplers/expansion_sampler.hpp"
#include "amp/roadmap/uas/hybrid_sampler.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"

namespace amp::roadmap {


struct HybridPrmSettings {
  HybridSettings hybrid;
  int k = 10;           // neighbours tried per new node (as `prm`)
  bool bridge = false;  // add the bridge test as a fifth sampler
  bool expansion = false;  // add PRM's expansion step as one more sampler (ExpansionSampler)
  DrawSequence sequence = DrawSequence::kRandom;  // how the samplers' domain draws its states
  static const core::SettingsSchema<HybridPrmSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

// Which samplers make_uas_samplers adds beyond the paper's four, and how they draw.
struct SamplerSetOptions {
  bool bridge = false;     // the bridge test (d = 2r)
  bool expansion = false;  // the expansion step (d = 2r), an observing arm
  DrawSequence sequence = DrawSequence::kRandom;  // used when the domain is null (a domain keeps its own)
  // Expansion candidates that exist before the run's first insertion (UAS's reused training
  // roadmap). Optional.
  std::shared_ptr<const VisibleNodes> known;
};

// The UAS sampler set (the UAS region-identification study, section 4.1.2; docs/uas.md), each restricted to `domain`
// (null = the whole space): uniform, Gaussian d = r, Gaussian d = 2r, OBPRM, and optionally the bridge
// test (d = 2r); r = the robot's smallest diameter (1% of the space extent for a point robot).
// Names: uniform, gaussian_r, gaussian_2r, obprm, bridge, expansion. Each counts into ctx.checker.
std::vector<HybridSampler::Arm> make_uas_samplers(const PlanningContext& ctx,
                                                  std::shared_ptr<const SamplingDomain> domain,
                                                  const SamplerSetOptions& options = {});

// Hybrid PRM: PRM whose sampler is a HybridSampler over make_uas_samplers(whole space), rewarded
// by UAS's structural reward. Extras: cc_* node classes, prob_/samples_/chosen_<sampler>,
// sampler_distance_fallback (1 when r = 0 and 1% of the extent stood in for it).
std::unique_ptr<Prm> make_hybrid_prm(const HybridPrmSettings& settings);


}  // namespace amp::roadmap
